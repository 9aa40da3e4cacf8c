#!/usr/bin/env bash
# CPU cost of the stress recovery (docs/stresses.md) on the demo's 3D synchronised deployment
# (examples/solar_array/sync-3d.yaml, 71 dofs): the superelements reduced without and with
# `--stresses all` (yoke 19 CBARs; panels 16 CQUAD4 + 14 CBARs), the scene run with each set, the
# two taking turns R times; prints the best and median CPU time (summary.json cpu_time_s) of each
# and checks that the run without stress modes writes the same history.csv and poses.csv bytes as
# the run with them (recovery on adds files, changes none).
#
# usage: bench/stress_recovery_cost.sh [--repeat R] SEFLEX
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repeat=3
if [ "${1:-}" = --repeat ]; then repeat="$2"; shift 2; fi
[ $# -eq 1 ] || { sed -n 2,9p "$0"; exit 2; }
bin="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for v in off on; do
  mkdir -p "$work/$v/superelements"
  extra=(); [ "$v" = on ] && extra=(--stresses all)
  "$bin" reduce "$root/meshes/yoke.bdf" --interface 1,3,4 --modes 10 "${extra[@]}" -o "$work/$v/superelements/yoke-3d.se" > /dev/null
  "$bin" reduce "$root/meshes/panel.bdf" --interface 1,2,3,4 --modes 10 "${extra[@]}" -o "$work/$v/superelements/panel-3d.se" > /dev/null
  cp "$root/examples/solar_array/sync-3d.yaml" "$work/$v/"
done
echo "# bench/stress_recovery_cost.sh --repeat $repeat $bin   ($(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg))"
declare -A cpu
for r in $(seq "$repeat"); do
  for v in off on; do
    (cd "$work/$v" && "$bin" run sync-3d.yaml -o "out$r" --force > /dev/null)
    cpu[$v]+="$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['cpu_time_s'])" "$work/$v/out$r/summary.json") "
  done
done
for v in off on; do
  python3 - "$v" ${cpu[$v]} <<'PY'
import statistics, sys
v = [float(x) for x in sys.argv[2:]]
print(f"stresses {sys.argv[1]:3s}: CPU best {min(v):.3f} s, median {statistics.median(v):.3f} s  ({len(v)} runs)")
PY
done
python3 - ${cpu[off]} -- ${cpu[on]} <<'PY'
import statistics, sys
a = sys.argv[1:]; i = a.index('--')
off, on = [float(x) for x in a[:i]], [float(x) for x in a[i + 1:]]
print(f"ratio on/off: median {statistics.median(on) / statistics.median(off):.3f}, best {min(on) / min(off):.3f}")
PY
for f in history.csv poses.csv events.csv; do
  cmp -s "$work/off/out1/$f" "$work/on/out1/$f" && echo "$f: identical with and without stress modes" || echo "$f: DIFFERS"
done
head -12 "$work/on/out1/stress_envelope.csv"
