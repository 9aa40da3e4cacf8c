#!/usr/bin/env bash
# Reader benchmark (issue 2): a deck of 1,000,000 CQUAD4 and 1,002,001 GRIDs in small-field,
# free-field and large-field format, read by `seflex info` (read + finalize + report) three times
# each; prints the median wall time and peak resident memory (GNU time -v).
#   bench/nastran_read_bench.sh [BUILD_DIR] [N] [RUNS]
# Needs the targets seflex and nastran_deck_gen built in BUILD_DIR (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
n="${2:-1001}"
runs="${3:-3}"
seflex="$build/apps/seflex"
gen="$build/bench/nastran_deck_gen"
for exe in "$seflex" "$gen"; do
  [ -x "$exe" ] || { echo "missing $exe: cmake --build $build --target seflex nastran_deck_gen" >&2; exit 2; }
done
[ -x /usr/bin/time ] || { echo "needs GNU time (/usr/bin/time, Debian package time)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "# nastran reader benchmark: N = $n ($((n * n)) GRID, $(((n - 1) * (n - 1))) CQUAD4), $runs runs, $(nproc) cores, $(date -I)"
printf "%-6s %10s %12s %12s %14s\n" format "deck MB" "median s" "min s" "peak RSS MB"
for format in small free large; do
  deck="$tmp/plate-$format.bdf"
  "$gen" "$deck" "$n" "$format"
  size_mb=$(( $(stat -c %s "$deck") / 1000000 ))
  times=()
  rss=0
  for ((r = 0; r < runs; ++r)); do
    /usr/bin/time -v "$seflex" info "$deck" > "$tmp/out.txt" 2> "$tmp/time.txt"
    t=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, a, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + a[i]; print s}' "$tmp/time.txt")
    k=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$tmp/time.txt")
    times+=("$t")
    (( k > rss )) && rss=$k
  done
  sorted=($(printf "%s\n" "${times[@]}" | sort -g))
  printf "%-6s %10d %12s %12s %14d\n" "$format" "$size_mb" "${sorted[$((runs / 2))]}" "${sorted[0]}" "$((rss / 1024))"
done
echo "# command: bench/nastran_read_bench.sh $build $n $runs"
