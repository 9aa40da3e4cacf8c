#!/usr/bin/env bash
# The main job of seflex, run by `scripts/bootstrap.sh demo`: the solar-array deployment demo
# (scripts/demo.sh) into demo-output/ (or $SEFLEX_OUT), refusing a folder that is neither empty nor
# a previous demo output.
#   scripts/main-job.sh [SEFLEX] [demo.sh options...]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build/apps/seflex}"
[ $# -gt 0 ] && shift
exec scripts/demo.sh "${SEFLEX_OUT:-demo-output}" --bin "$bin" "$@"
