#!/usr/bin/env bash
# CPU time of `seflex run` on the demo's 3D synchronised deployment (examples/solar_array/sync-3d.yaml:
# yoke + two panels, 10 fixed-interface modes each, full inertia, 71 dofs, run to 5 s after the last
# lock as the scene says) for one or more seflex builds side by side in one run, each run R times
# (the best and the median are printed). The superelements are reduced once, by the last build.
#
# usage: bench/demo_run_speed.sh [--repeat R] SEFLEX [SEFLEX ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repeat=3
if [ "${1:-}" = "--repeat" ]; then repeat="$2"; shift 2; fi
[ $# -ge 1 ] || { sed -n 2,7p "$0"; exit 2; }
bins=("$@")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/superelements"
reducer="${bins[-1]}"
"$reducer" reduce "$root/meshes/yoke.bdf" --interface 1,3,4 --modes 10 -o "$work/superelements/yoke-3d.se" > /dev/null
"$reducer" reduce "$root/meshes/panel.bdf" --interface 1,2,3,4 --modes 10 -o "$work/superelements/panel-3d.se" > /dev/null
cp "$root/examples/solar_array/sync-3d.yaml" "$work/"
echo "# bench/demo_run_speed.sh --repeat $repeat ${bins[*]}   ($(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores)"
printf "%-40s %9s %9s %8s %10s %s\n" build "best CPU" "median" steps iterations "simulated"
for b in "${bins[@]}"; do
  times=()
  for r in $(seq "$repeat"); do
    out="$work/out-$r"
    /usr/bin/time -f "%U %S" -o "$work/time" "$b" run "$work/sync-3d.yaml" -o "$out" --no-animation --force > "$work/log" 2>&1
    times+=("$(awk '{printf "%.3f", $1 + $2}' "$work/time")")
  done
  sorted=($(printf "%s\n" "${times[@]}" | sort -g))
  steps=$(grep -oE "[0-9]+ steps" "$work/log" | head -1 | cut -d' ' -f1)
  iters=$(grep -oE "[0-9]+ Newton iterations" "$work/log" | head -1 | cut -d' ' -f1)
  tend=$(tail -1 "$out/history.csv" | cut -d, -f1)
  printf "%-40s %9s %9s %8s %10s %s s\n" "$b" "${sorted[0]}" "${sorted[$((repeat / 2))]}" "${steps:-?}" "${iters:-?}" "$tend"
done
