#!/usr/bin/env bash
# Coverage-guided fuzzing of every reader (issue 17): builds the libFuzzer harnesses of fuzz/ and runs
# each for SECONDS, one after the other; prints per harness the executions per second, the coverage
# (edges, libFuzzer's "cov"), the corpus size and any findings, then the command that produced them.
#   bench/fuzz.sh [SECONDS] [HARNESS...]       (default 60 s; harnesses: nastran dmig gmsh scene superelement)
# Environment:
#   SEFLEX_FUZZ_DIR    corpora, seeds, findings and logs (default ~/.cache/seflex-fuzz; outside the tree)
#   SEFLEX_FUZZ_BUILD  build folder (default build-fuzz: clang, -DSEFLEX_FUZZ=ON, RelWithDebInfo; the folder
#                      of the sanitizer stage of scripts/bootstrap.sh test, which runs this script 20 s)
#   SEFLEX_JOBS        build parallelism (default 1)
#   SEFLEX_FUZZ_NICE   nice level of the fuzzers (default 15)
#   SEFLEX_FUZZ_NO_BUILD=1  use the binaries already built
#   SEFLEX_FUZZ_SEED   libFuzzer's -seed (CI sets 1: the same mutations every run; default random)
# The corpus of each harness ($SEFLEX_FUZZ_DIR/<harness>/corpus) is kept between runs and grows; the
# seeds are copied afresh each run from tests/, meshes/, examples/, bench/study/ and ../shared/validation/.
# A finding (crash, sanitizer report, leak, timeout > 10 s, > 2 GB) is saved under <harness>/findings/;
# reproduce it with `<build>/fuzz/fuzz_<harness> FILE`. Exit status: 0 if no harness found anything.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
seconds="${1:-60}"
shift || true
all=(nastran dmig gmsh scene superelement op4)
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all[@]}")
build="${SEFLEX_FUZZ_BUILD:-build-fuzz}"
dir="${SEFLEX_FUZZ_DIR:-$HOME/.cache/seflex-fuzz}"
jobs="${SEFLEX_JOBS:-1}"
nice_level="${SEFLEX_FUZZ_NICE:-15}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac

if [ "${SEFLEX_FUZZ_NO_BUILD:-0}" != 1 ]; then
  # the configuration of the sanitizer stage of scripts/bootstrap.sh test (its functions, sourced)
  source scripts/bootstrap.sh
  bootstrap_tools
  configure_fuzz "$build"
  cmake --build "$build" -j "$jobs" --target fuzz_all seflex
fi

# ---- seeds --------------------------------------------------------------------------------------
shared="$root/../shared/validation"
seed_dirs=(tests meshes examples bench/study)
[ -d "$shared" ] && seed_dirs+=("$shared")
copy_seeds() {  # harness, find-expression...
  local h="$1"; shift
  find "${seed_dirs[@]}" -type f \( "$@" \) -size -64k -print0 2>/dev/null |
    while IFS= read -r -d '' f; do cp "$f" "$dir/$h/seeds/$(echo "$f" | tr '/' '_')"; done
}
make_seeds() {  # harness
  local h="$1" s="$dir/$1/seeds"
  rm -rf "$s"
  mkdir -p "$s" "$dir/$h/corpus" "$dir/$h/findings"
  case "$h" in
    nastran)
      copy_seeds nastran -iname '*.bdf' -o -iname '*.dat' -o -iname '*.nas' ;;
    dmig)  # bulk data appended to fuzz_dmig's fixed deck (grids 1-3, scalar point 10)
      printf 'DMIG,KX,0,6,1,0\nDMIG,KX,2,3,,2,3,1.e5\nDMIG,KX,3,3,,2,3,-1.e5,,3,3,1.e5\n' >"$s/kx"
      printf 'DMIG,MX,0,6,1,0\nDMIG,MX,10,0,,10,0,2.\nDMIG,MX,3,1,,3,1,0.5\nPARAM,CM2,2.\n' >"$s/mx"
      printf 'DMIG    KX      0       6       2       0\nDMIG*   KX              1               2\n*       1               2               3.0D4\n' >"$s/large"
      printf 'DMIG,KX,0,6,1,0\nDMIG,KX,1,1,,1,1,1.e3,,2,1,-1.e3\nDMIG,MX,0,6,1,0\nDMIG,MX,1,1,,1,1,1.\nPARAM,CK2,0.5\n' >"$s/both" ;;
    op4)  # OUTPUT4 text: the .op4 files of tests/ under 64 kB and a dense double-precision matrix
      copy_seeds op4 -iname '*.op4'
      printf '       2       2       6       2KAA     1P,3E23.16\n       1       1       2\n 1.0000000000000000E+00-5.0000000000000000E-01\n       2       1       2\n-5.0000000000000000E-01 2.0000000000000000E+00\n       3       1       1\n 0.0000000000000000E+00\n' >"$s/dense" ;;
    gmsh)
      copy_seeds gmsh -iname '*.msh'
      for f in tests/data/gmsh/*.msh; do  # the panel with its own companion file
        { cat "$f"; printf '\n$seflex-fuzz-props\n'; cat meshes/panel.props.bdf; } >"$s/props_$(basename "$f")"
      done ;;
    scene)  # every superelement named link.se (the harness's scratch folder holds that one)
      find examples bench/study -name '*.yaml' -print0 | while IFS= read -r -d '' f; do
        sed -E 's#(superelement: *)[^,}]*#\1link.se#' "$f" >"$s/$(echo "$f" | tr '/' '_')"
      done ;;
    superelement)  # first byte odd: the file as is; even: body, the harness appends the SHA-256 trailer
      local t; t="$(mktemp -d)"
      "$build/apps/seflex" reduce examples/scenes/link.bdf --interface 1,5 --frame 3 --modes 3 -o "$t/link.se" >/dev/null
      "$build/apps/seflex" reduce examples/scenes/link.bdf --interface 1,5 --modes 0 --no-mesh -o "$t/nomesh.se" >/dev/null
      for f in "$t"/*.se; do
        { printf '\001'; cat "$f"; } >"$s/file_$(basename "$f")"
        { printf '\000'; head -c $(($(stat -c %s "$f") - 40)) "$f"; } >"$s/body_$(basename "$f")"
      done
      rm -rf "$t" ;;
    *) echo "fuzz.sh: unknown harness '$h' (have: ${all[*]})" >&2; exit 2 ;;
  esac
}

# ---- runs ---------------------------------------------------------------------------------------
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
status=0
rows=()
for h in "${harnesses[@]}"; do
  exe="$build/fuzz/fuzz_$h"
  [ -x "$exe" ] || { echo "fuzz.sh: missing $exe" >&2; exit 2; }
  make_seeds "$h"
  log="$dir/$h/last.log"
  before=$(find "$dir/$h/findings" -type f | wc -l)
  cmd=(nice -n "$nice_level" "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536
       -dict="$root/fuzz/dict/$h.dict" -artifact_prefix="$dir/$h/findings/" -print_final_stats=1)
  [ -n "${SEFLEX_FUZZ_SEED:-}" ] && cmd+=(-seed="$SEFLEX_FUZZ_SEED")
  cmd+=("$dir/$h/corpus" "$dir/$h/seeds")
  echo "== $h: ${cmd[*]}"
  rc=0
  t0=$(date +%s)
  "${cmd[@]}" >"$log" 2>&1 || rc=$?
  elapsed=$(($(date +%s) - t0))
  after=$(find "$dir/$h/findings" -type f | wc -l)
  last=$(grep -E '^#[0-9]+.*(cov|DONE)' "$log" | tail -1 || true)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(echo "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
  ft=$(echo "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')
  files=$(find "$dir/$h/corpus" -type f | wc -l)
  bytes=$(du -sk --apparent-size "$dir/$h/corpus" | cut -f1)
  rows+=("$(printf '%-13s %6s %10s %8s %7s %7s %7s %8s %9s' "$h" "$elapsed" "${execs:-?}" "${rate:-?}" \
    "${cov:-?}" "${ft:-?}" "$files" "${bytes}K" "$((after - before))")")
  if [ "$rc" -ne 0 ] || [ "$after" -gt "$before" ]; then
    status=1
    echo "   FINDING (exit $rc): $(grep -m1 -E 'ERROR: |==ERROR|runtime error|not an InputError|deadly signal' "$log" || true)"
    echo "   log: $log; inputs: $dir/$h/findings/"
    echo "   ---- end of the log:"; tail -n 40 "$log" | sed 's/^/   | /'
  fi
done

echo
echo "# bench/fuzz.sh $seconds ${harnesses[*]}   ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, nice $nice_level, $(clang --version | head -1))"
printf '%-13s %6s %10s %8s %7s %7s %7s %8s %9s\n' harness seconds execs exec/s cov ft corpus size findings
for r in "${rows[@]}"; do echo "$r"; done
echo "# corpora and logs: $dir/<harness>/{corpus,last.log,findings}"
exit $status
