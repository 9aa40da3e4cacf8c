#!/usr/bin/env bash
# The solar-array deployment demo, end to end (../shared/docs/solar-array.md, issue 8): the main job
# of seflex, run by `scripts/bootstrap.sh demo`.
#
#   scripts/demo.sh [OUTDIR] [--force] [--bin SEFLEX] [--t-end T] [--no-plots] [--jobs N]
#   (--jobs: runs and reductions at a time, default $SEFLEX_JOBS or 2)
#
# 1. reduces meshes/yoke.bdf and meshes/panel.bdf to the four Craig-Bampton superelements, with
#    their stress modes (--stresses all: stress_envelope.csv and the peak element results of each run)
#    (beam-like: yoke {1,5}, panel {5,6}; 3D: yoke {1,3,4}, panel {1,2,3,4}) in OUTDIR/superelements/;
# 2. copies the four scenes of examples/solar_array/ ({unsync,sync} x {beam,3d}) to OUTDIR/;
# 3. runs them with `seflex run` (OUTDIR/<case>/: history.csv, events.csv, summary.json, animation.pvd);
# 4. plots them and computes the metrics (scripts/plot_solar_array.py: OUTDIR/plots/*.png,
#    OUTDIR/metrics.json) and prints the results table.
# OUTDIR defaults to demo-output/. An existing non-empty OUTDIR is used only if it is a previous demo
# output (it holds .seflex-demo) or with --force; files this script writes are replaced, others kept.
# --t-end T stops every run at T s (shorter variants for tests). Exit status: 0 ok, 1 failure, 2 usage.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="demo-output"
bin="$root/build/apps/seflex"
force=0
plots=1
t_end=()
jobs="${SEFLEX_JOBS:-2}"
out_set=0
usage() { sed -n '5,16p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --force) force=1 ;;
    --bin) [ $# -ge 2 ] || usage; bin="$2"; shift ;;
    --t-end) [ $# -ge 2 ] || usage; t_end=(--t-end "$2"); shift ;;
    --no-plots) plots=0 ;;
    --jobs) [ $# -ge 2 ] || usage; jobs="$2"; shift ;;
    -h|--help) usage ;;
    -*) echo "demo: unknown option '$1'" >&2; usage ;;
    *) [ "$out_set" = 0 ] || { echo "demo: more than one output folder given" >&2; usage; }; out="$1"; out_set=1 ;;
  esac
  shift
done
[ -x "$bin" ] || { echo "demo: seflex not found at '$bin' (build it, or pass --bin)" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
python=/usr/bin/python3   # Debian's python3 with numpy and matplotlib (scripts/install-deps.sh)

# Never destroy user files: an existing non-empty folder must be a previous demo output.
if [ -e "$out" ] && [ ! -d "$out" ]; then
  echo "demo: '$out' exists and is not a folder" >&2; exit 1
fi
if [ -d "$out" ] && [ -n "$(ls -A "$out")" ] && [ ! -f "$out/.seflex-demo" ] && [ "$force" = 0 ]; then
  echo "demo: '$out' is not empty and is not a previous demo output; choose another folder or pass --force" >&2
  exit 1
fi
mkdir -p "$out/superelements"
out="$(cd "$out" && pwd)"
echo "seflex solar-array demo $(date -u +%Y-%m-%dT%H:%M:%SZ)" > "$out/.seflex-demo"
cases=(unsync-beam unsync-3d sync-beam sync-3d)
timings="$out/timings.txt"
: > "$timings"
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }
t_demo=$(now)

# Run the commands of a list file (one per line), at most $jobs at a time; fail if any fails.
run_parallel() {
  local list="$1" pids=() line rc=0
  while IFS= read -r line; do
    bash -c "$line" &
    pids+=($!)
    if [ "${#pids[@]}" -ge "$jobs" ]; then wait "${pids[0]}" || rc=1; pids=("${pids[@]:1}"); fi
  done < "$list"
  for p in "${pids[@]}"; do wait "$p" || rc=1; done
  return $rc
}

# 1. Reductions. Interface sets of solar-array.md; fixed-interface modes per superelement chosen
#    by convergence of the lock times and lock torques (docs/solar-array-results.md, "Number of
#    fixed-interface modes"): 10 each (both reductions are converged with 10: 20 change the lock times
#    by 0.1 ms and the lock torques by less than 0.5 %).
t0=$(now)
list="$out/.reduce.cmds"
: > "$list"
while read -r body set tag modes; do
  echo "'$bin' reduce '$root/meshes/$body.bdf' --interface $set --modes $modes --stresses all --name $body-$tag -o '$out/superelements/$body-$tag.se' --force > '$out/superelements/$body-$tag.log' 2>&1 || { echo 'demo: seflex reduce failed, see $out/superelements/$body-$tag.log' >&2; exit 1; }" >> "$list"
done <<EOF
yoke 1,5 beam 10
panel 5,6 beam 10
yoke 1,3,4 3d 10
panel 1,2,3,4 3d 10
EOF
run_parallel "$list"
rm -f "$list"
echo "reductions (4 superelements) $(elapsed "$t0") s" | tee -a "$timings"

# 2. Scenes.
for c in "${cases[@]}"; do cp "$root/examples/solar_array/$c.yaml" "$out/$c.yaml"; done

# 3. Runs: two at a time (2 cores), each timed.
list="$out/.run.cmds"
: > "$list"
for c in unsync-3d sync-3d unsync-beam sync-beam; do
  echo "s=\$(date +%s.%N); '$bin' run '$out/$c.yaml' -o '$out/$c' --force ${t_end[*]} > '$out/$c.log' 2>&1 || { echo 'demo: seflex run $c failed, see $out/$c.log' >&2; exit 1; }; echo \"run $c \$(awk -v a=\$s -v b=\$(date +%s.%N) 'BEGIN { printf \"%.2f\", b - a }') s\" >> '$timings'" >> "$list"
done
t0=$(now)
run_parallel "$list"
rm -f "$list"
echo "runs (4 cases, $jobs at a time) $(elapsed "$t0") s" | tee -a "$timings"
grep '^run ' "$timings" | sed 's/^/  /'

# 4. Plots, metrics, results table.
t0=$(now)
plot_args=()
[ "$plots" = 1 ] || plot_args=(--no-plots)
"$python" "$root/scripts/plot_solar_array.py" "$out" "${plot_args[@]}"
echo "metrics$([ "$plots" = 1 ] && echo " and plots") $(elapsed "$t0") s" | tee -a "$timings"
echo "demo total $(elapsed "$t_demo") s" | tee -a "$timings"
echo "results in $out (plots/, metrics.json; animations: paraview $out/<case>/animation.pvd)"
