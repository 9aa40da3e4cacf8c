#!/usr/bin/env bash
# CPU time of `seflex run` on the demo's 3D synchronised deployment (examples/solar_array/sync-3d.yaml:
# yoke + two panels, 10 fixed-interface modes each, full inertia, 71 dofs, run to 5 s after the last
# lock as the scene says) for one or more seflex builds side by side in one run, each run R times,
# the builds taking turns in every round (so that a busy spell of the shared machine hits all of
# them); the best and the median CPU time (user + system) are printed. The superelements are reduced
# once, by the last build. --no-velocity-tangent: the last build also runs the scene with
# `integrator.newton.inertia_velocity_tangent: false` (printed as BUILD [no velocity tangent]).
#
# usage: bench/demo_run_speed.sh [--repeat R] [--no-velocity-tangent] SEFLEX [SEFLEX ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repeat=3
novt=0
while [ $# -gt 0 ]; do
  case "$1" in
    --repeat) repeat="$2"; shift 2 ;;
    --no-velocity-tangent) novt=1; shift ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { sed -n 2,10p "$0"; exit 2; }
bins=("$@")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/superelements"
reducer="${bins[-1]}"
"$reducer" reduce "$root/meshes/yoke.bdf" --interface 1,3,4 --modes 10 -o "$work/superelements/yoke-3d.se" > /dev/null
"$reducer" reduce "$root/meshes/panel.bdf" --interface 1,2,3,4 --modes 10 -o "$work/superelements/panel-3d.se" > /dev/null
cp "$root/examples/solar_array/sync-3d.yaml" "$work/"
# Configurations: "binary|scene|label".
configs=()
for b in "${bins[@]}"; do configs+=("$b|sync-3d.yaml|$b"); done
if [ "$novt" = 1 ]; then
  sed 's/^  stop: {after_all_locked: \(.*\)}$/  stop: {after_all_locked: \1}\n  newton: {inertia_velocity_tangent: false}/' \
    "$work/sync-3d.yaml" > "$work/sync-3d-novt.yaml"
  grep -q inertia_velocity_tangent "$work/sync-3d-novt.yaml" || { echo "could not edit the scene" >&2; exit 1; }
  configs+=("${bins[-1]}|sync-3d-novt.yaml|${bins[-1]} [no velocity tangent]")
fi
echo "# bench/demo_run_speed.sh --repeat $repeat$([ "$novt" = 1 ] && echo " --no-velocity-tangent") ${bins[*]}   ($(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg))"
declare -A times
for r in $(seq "$repeat"); do
  for k in "${!configs[@]}"; do
    IFS='|' read -r b scene label <<< "${configs[$k]}"
    out="$work/out-$k"
    /usr/bin/time -f "%U %S" -o "$work/time" "$b" run "$work/$scene" -o "$out" --no-animation --force > "$work/log-$k" 2>&1
    times[$k]="${times[$k]:-} $(awk '{printf "%.3f", $1 + $2}' "$work/time")"
  done
done
printf "%-56s %9s %9s %8s %10s %s\n" build "best CPU" "median" steps iterations "simulated"
for k in "${!configs[@]}"; do
  IFS='|' read -r b scene label <<< "${configs[$k]}"
  sorted=($(printf "%s\n" ${times[$k]} | sort -g))
  steps=$(grep -oE "[0-9]+ steps" "$work/log-$k" | head -1 | cut -d' ' -f1)
  iters=$(grep -oE "[0-9]+ Newton iterations" "$work/log-$k" | head -1 | cut -d' ' -f1)
  tend=$(tail -1 "$work/out-$k/history.csv" | cut -d, -f1)
  printf "%-56s %9s %9s %8s %10s %s s\n" "$label" "${sorted[0]}" "${sorted[$((repeat / 2))]}" "${steps:-?}" "${iters:-?}" "$tend"
done
