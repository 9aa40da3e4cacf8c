#!/usr/bin/env bash
# The main job of seflex, run by `scripts/bootstrap.sh demo`.
# Until the solar-array demo exists: describe and analyse the demonstration yoke from meshes/.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build/apps/seflex}"
out="${SEFLEX_OUT:-out}"
mkdir -p "$out"
for deck in meshes/*.bdf; do
  [ -f "$deck" ] || continue
  "$bin" info "$deck"
  "$bin" modes "$deck" --count 12 --csv "$out/$(basename "$deck" .bdf)-modes.csv"
done
