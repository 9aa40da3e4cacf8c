#!/usr/bin/env bash
# Cost per Newton iteration of the demo's 3D synchronised deployment (examples/solar_array/sync-3d.yaml,
# full inertia) with its two panels replaced by refined panels of bench/refined_panel.py (NY x NZ CQUAD4,
# interfaces 1-4, 10 fixed-interface modes), for one or more seflex builds side by side in one run
# (issue 12: the time loop must cost what the reduced coordinates cost, not what the mesh costs).
#
# usage: bench/mesh_independence.sh [--t-end T] [--sizes "NYxNZ ..."] SEFLEX [SEFLEX ...]
#   e.g. bench/mesh_independence.sh /path/to/old/seflex build/apps/seflex
# Prints, per panel and build: grids, CPU time (user+sys), Newton iterations, microseconds per iteration.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
t_end=1.0
sizes="4x4 20x24 60x72"
while [ $# -gt 0 ]; do
  case "$1" in
    --t-end) t_end="$2"; shift 2 ;;
    --sizes) sizes="$2"; shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { sed -n 2,9p "$0"; exit 2; }
bins=("$@")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
reducer="${bins[-1]}"
mkdir -p "$work/superelements"
"$reducer" reduce "$root/meshes/yoke.bdf" --interface 1,3,4 --modes 10 --name yoke-3d -o "$work/superelements/yoke-3d.se" > /dev/null
echo "# bench/mesh_independence.sh --t-end $t_end --sizes \"$sizes\" ${bins[*]}   ($(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores)"
printf "%-8s %7s  %-40s %9s %10s %12s\n" panel grids build "CPU s" iterations "us/iteration"
for size in $sizes; do
  ny="${size%x*}"; nz="${size#*x}"
  /usr/bin/python3 "$root/bench/refined_panel.py" "$ny" "$nz" "$work/panel-$size.bdf" > /dev/null
  "$reducer" reduce "$work/panel-$size.bdf" --interface 1,2,3,4 --modes 10 --name panel-3d -o "$work/superelements/panel-3d.se" --force > /dev/null
  grids=$(( (ny + 1) * (nz + 1) + 6 ))
  sed -e "s/t_end: 30.0 /t_end: $t_end /" "$root/examples/solar_array/sync-3d.yaml" > "$work/scene.yaml"
  for bin in "${bins[@]}"; do
    out="$work/out"
    rm -rf "$out"
    /usr/bin/time -f "%U %S" -o "$work/time" "$bin" run "$work/scene.yaml" -o "$out" --no-animation > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
    read -r u s < "$work/time"
    it=$(sed -n 's/.* \([0-9]*\) Newton iterations.*/\1/p' "$work/log")
    cpu=$(echo "$u + $s" | bc -l)
    printf "%-8s %7d  %-40s %9.2f %10d %12.1f\n" "$size" "$grids" "$bin" "$cpu" "$it" "$(echo "1e6 * $cpu / $it" | bc -l)"
  done
done
