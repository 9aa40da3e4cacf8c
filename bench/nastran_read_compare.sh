#!/usr/bin/env bash
# Reader benchmark, two builds side by side: `seflex info` on the 1,000,000-CQUAD4 deck of
# nastran_read_bench.sh, the two executables alternating (A B A B ...) so that both see the same load;
# prints the fastest and the median wall time of each, the fastest CPU time (user + system: less
# sensitive to other processes on a loaded machine) and the ratios B/A, per format.
#   bench/nastran_read_compare.sh SEFLEX_A SEFLEX_B [DECK_GEN] [N] [RUNS] [FORMATS]
# DECK_GEN: a built bench/nastran_deck_gen (default build/bench/nastran_deck_gen); N = 1001, RUNS = 5,
# FORMATS = "small free large".
set -euo pipefail
cd "$(dirname "$0")/.."
a="$1"
b="$2"
gen="${3:-build/bench/nastran_deck_gen}"
n="${4:-1001}"
runs="${5:-5}"
formats="${6:-small free large}"
for exe in "$a" "$b" "$gen"; do
  [ -x "$exe" ] || { echo "missing executable $exe" >&2; exit 2; }
done
[ -x /usr/bin/time ] || { echo "needs GNU time (/usr/bin/time, Debian package time)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
# run EXE DECK OUT: prints "wall cpu" in seconds
run() { /usr/bin/time -f "%e %U %S" -o "$tmp/t.txt" "$1" info "$2" > "$3"; awk '{printf "%s %.2f\n", $1, $2 + $3}' "$tmp/t.txt"; }
echo "# seflex info, A = $a, B = $b: N = $n ($((n * n)) GRID, $(((n - 1) * (n - 1))) CQUAD4), $runs runs each alternating, $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-6s %7s %9s %9s %9s %9s %9s %9s %8s %8s\n" format "deck MB" "A best s" "A median" "A cpu s" "B best s" "B median" "B cpu s" "B/A wall" "B/A cpu"
for format in $formats; do
  deck="$tmp/plate-$format.bdf"
  "$gen" "$deck" "$n" "$format"
  size_mb=$(( $(stat -c %s "$deck") / 1000000 ))
  "$a" info "$deck" > /dev/null  # page cache warm
  ta=()
  tb=()
  ca=()
  cb=()
  for ((r = 0; r < runs; ++r)); do
    read -r w c < <(run "$a" "$deck" "$tmp/a.txt"); ta+=("$w"); ca+=("$c")
    read -r w c < <(run "$b" "$deck" "$tmp/b.txt"); tb+=("$w"); cb+=("$c")
  done
  # the same report from both (apart from the deck path)
  if ! cmp -s "$tmp/a.txt" "$tmp/b.txt"; then
    echo "# note: the two reports differ for $format:"
    diff "$tmp/a.txt" "$tmp/b.txt" | head -6 || true
  fi
  sa=($(printf "%s\n" "${ta[@]}" | sort -g))
  sb=($(printf "%s\n" "${tb[@]}" | sort -g))
  xa=($(printf "%s\n" "${ca[@]}" | sort -g))
  xb=($(printf "%s\n" "${cb[@]}" | sort -g))
  printf "%-6s %7d %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f %8.3f %8.3f\n" "$format" "$size_mb" "${sa[0]}" "${sa[$((runs / 2))]}" \
    "${xa[0]}" "${sb[0]}" "${sb[$((runs / 2))]}" "${xb[0]}" "$(echo "${sb[0]} / ${sa[0]}" | bc -l)" "$(echo "${xb[0]} / ${xa[0]}" | bc -l)"
done
echo "# command: bench/nastran_read_compare.sh $a $b $gen $n $runs \"$formats\""
