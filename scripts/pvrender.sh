#!/usr/bin/env bash
# Render one step of a seflex .pvd series with ParaView's own Python (pvbatch) on a virtual display.
# ParaView's Python modules come from the python3-paraview package unpacked by install-deps.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
pv_prefix="${SEFLEX_PARAVIEW_PY:-/opt/seflex/paraview-python}"
export PYTHONPATH="$pv_prefix/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
command -v pvbatch >/dev/null || { echo "pvrender: pvbatch not found (run scripts/install-deps.sh)" >&2; exit 2; }
[ -f "$pv_prefix/usr/lib/python3/dist-packages/paraview/simple.py" ] || { echo "pvrender: ParaView Python not found in $pv_prefix (run scripts/install-deps.sh)" >&2; exit 2; }
# xvfb-run now and then hands pvbatch a display whose server is not up yet ("bad X server
# connection", SIGABRT; seen about once in ten runs on a loaded machine): try up to three times,
# and only for that failure.
for attempt in 1 2 3; do
  if log="$(xvfb-run -a -s "-screen 0 1024x768x24" pvbatch "$here/pvrender.py" "$@" 2>&1)"; then
    printf '%s\n' "$log"
    exit 0
  fi
  if ! grep -q 'bad X server connection' <<<"$log" || [ "$attempt" = 3 ]; then
    printf '%s\n' "$log" >&2
    exit 1
  fi
  echo "pvrender: the virtual X server was not ready (attempt $attempt of 3), retrying" >&2
  sleep 1
done
