#!/bin/sh
# Craig-Bampton reduction benchmark (issue 5): `seflex reduce` of a refined solar-array panel
# (bench/refined_panel.py: same geometry and properties as meshes/panel.bdf) with the four hinge
# points 1-4 as interface and 30 fixed-interface modes; wall time and peak memory from GNU time.
#
# usage: bench/reduction_bench.sh BUILD_DIR [NY NZ [RUNS]]   (default 372 448 1: about 1.0M dofs)
# Prints, per run, the wall time, the peak resident memory and seflex's own phase times, then the
# median, and the command that produced them.
set -eu
build=${1:?usage: bench/reduction_bench.sh BUILD_DIR [NY NZ [RUNS]]}
ny=${2:-372}
nz=${3:-448}
runs=${4:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
seflex="$build/apps/seflex"
[ -x "$seflex" ] || { echo "no $seflex: build the seflex target first" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/seflex-reduction-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT
deck="$work/panel_${ny}x${nz}.bdf"
/usr/bin/python3 "$root/bench/refined_panel.py" "$ny" "$nz" "$deck"
dofs=$(( 6 * ((ny + 1) * (nz + 1) + 6) ))
echo "model: refined panel ${ny} x ${nz} CQUAD4, $(( (ny + 1) * (nz + 1) + 6 )) grids, $dofs dofs ($(du -h "$deck" | cut -f1) deck)"
times=""
for run in $(seq 1 "$runs"); do
  /usr/bin/time -v "$seflex" reduce "$deck" --interface 1,2,3,4 --modes 30 -o "$work/panel.se" --force \
    > "$work/out.txt" 2> "$work/time.txt"
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time.txt" |
         awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time.txt")
  user=$(sed -n 's/.*User time (seconds): //p' "$work/time.txt")
  sys=$(sed -n 's/.*System time (seconds): //p' "$work/time.txt")
  printf 'run %d: wall %.1f s, CPU %.1f s (user %.1f + system %.1f), peak RSS %.2f GB, load average %s\n' "$run" "$wall" \
    "$(echo "$user + $sys" | bc -l)" "$user" "$sys" "$(echo "$rss / 1048576" | bc -l)" "$(cut -d' ' -f1-3 /proc/loadavg)"
  grep -E '^(time|work):' "$work/out.txt" | sed 's/^/  seflex /'
  times="$times $wall"
done
grep -E 'fixed-interface modes:|first neglected|wrote' "$work/out.txt" | sed 's/^/  /'
median=$(echo "$times" | tr ' ' '\n' | grep . | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }')
echo "median wall time over $runs run(s): $median s (target: < 90 s, < 8 GB)"
echo "command: bench/reduction_bench.sh $build $ny $nz $runs"
