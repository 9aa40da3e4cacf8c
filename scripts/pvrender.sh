#!/usr/bin/env bash
# Render one step of a seflex .pvd series with ParaView's own Python (pvbatch) on a virtual display.
# ParaView's Python modules come from the python3-paraview package unpacked by install-deps.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
pv_prefix="${SEFLEX_PARAVIEW_PY:-/opt/seflex/paraview-python}"
export PYTHONPATH="$pv_prefix/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
command -v pvbatch >/dev/null || { echo "pvrender: pvbatch not found (run scripts/install-deps.sh)" >&2; exit 2; }
[ -f "$pv_prefix/usr/lib/python3/dist-packages/paraview/simple.py" ] || { echo "pvrender: ParaView Python not found in $pv_prefix (run scripts/install-deps.sh)" >&2; exit 2; }
# The virtual display: Xvfb picks a free display number itself and writes it to a file once it
# accepts connections (-displayfd), so two renders at once (CTest -j, the demo) cannot race for one
# number, and pvbatch never meets a server that is not up yet (xvfb-run -a did both on a loaded
# machine: "bad X server connection", SIGABRT). A render that still meets that failure is retried.
command -v Xvfb >/dev/null || { echo "pvrender: Xvfb not found (run scripts/install-deps.sh)" >&2; exit 2; }
tmp="$(mktemp -d)"
xvfb_pid=""
cleanup() {
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
start_display() {
  : > "$tmp/display"
  Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
  xvfb_pid=$!
  for _ in $(seq 600); do  # up to 60 s on a loaded machine
    if [ -s "$tmp/display" ] && grep -q '[0-9]' "$tmp/display"; then
      DISPLAY=":$(tr -dc '0-9' < "$tmp/display")"
      export DISPLAY
      return 0
    fi
    kill -0 "$xvfb_pid" 2>/dev/null || break
    sleep 0.1
  done
  echo "pvrender: the virtual X server (Xvfb) did not start: $(tail -3 "$tmp/xvfb.log")" >&2
  return 1
}
for attempt in 1 2 3; do
  start_display || exit 1
  if log="$(pvbatch "$here/pvrender.py" "$@" 2>&1)"; then
    printf '%s\n' "$log"
    exit 0
  fi
  if ! grep -q 'bad X server connection' <<<"$log" || [ "$attempt" = 3 ]; then
    printf '%s\n' "$log" >&2
    exit 1
  fi
  echo "pvrender: the virtual X server was not ready (attempt $attempt of 3), retrying" >&2
  kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  xvfb_pid=""
  sleep 1
done
