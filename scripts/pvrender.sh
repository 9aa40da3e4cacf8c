#!/usr/bin/env bash
# Render one step of a seflex .pvd series with ParaView's own Python (pvbatch) on a virtual display.
# ParaView's Python modules come from the python3-paraview package unpacked by install-deps.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
pv_prefix="${SEFLEX_PARAVIEW_PY:-/opt/seflex/paraview-python}"
export PYTHONPATH="$pv_prefix/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
command -v pvbatch >/dev/null || { echo "pvrender: pvbatch not found (run scripts/install-deps.sh)" >&2; exit 2; }
[ -f "$pv_prefix/usr/lib/python3/dist-packages/paraview/simple.py" ] || { echo "pvrender: ParaView Python not found in $pv_prefix (run scripts/install-deps.sh)" >&2; exit 2; }
exec xvfb-run -a -s "-screen 0 1024x768x24" pvbatch "$here/pvrender.py" "$@"
