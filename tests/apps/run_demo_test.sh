#!/usr/bin/env bash
# CTest `demo_solar_array` (tests/CMakeLists.txt): runs the solar-array demo end to end at its
# production settings (scripts/demo.sh: 4 reductions, 4 runs, plots, metrics), reruns sync-beam
# with 100x stiffer cables and sync-3d at its preview settings, checks the issue's required results (tests/apps/check_demo.py), and
# renders the last frame of the sync-3d animation with ParaView's own Python (scripts/pvrender.sh),
# checking the point and cell counts ParaView read against the FE decks (all grids and elements of
# the yoke and twice the panel).
#   tests/apps/run_demo_test.sh SEFLEX OUTDIR
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
bin="$1"
out="$2"
"$root/scripts/demo.sh" "$out" --force --bin "$bin"
# The synchronised beam-like case again with 100x stiffer cables (check_demo.py says why).
sed 's/stiffness: 2.05e5/stiffness: 2.05e7/' "$out/sync-beam.yaml" > "$out/sync-beam-stiff-cables.yaml"
grep -q 'stiffness: 2.05e7' "$out/sync-beam-stiff-cables.yaml"
"$bin" run "$out/sync-beam-stiff-cables.yaml" -o "$out/sync-beam-stiff-cables" --force --no-animation > "$out/sync-beam-stiff-cables.log" 2>&1 \
  || { cat "$out/sync-beam-stiff-cables.log"; exit 1; }
# The synchronised 3D case at its preview settings (docs/solar-array-results.md, "Preview settings"):
# 2 of the 10 fixed-interface modes per body, local error 1e-4, steps up to the 5 ms output interval.
sed -e 's/^    inertia: full$/&\n    internal_modes: 2/' -e 's/^  max_step: 2.5e-3 .*$/  max_step: 5.0e-3/' \
    -e 's/tolerance: {position: 1.0e-5, angle: 1.0e-5}/tolerance: {position: 1.0e-4, angle: 1.0e-4}/' \
    "$out/sync-3d.yaml" > "$out/sync-3d-preview.yaml"
[ "$(grep -c '^    internal_modes: 2$' "$out/sync-3d-preview.yaml")" = 3 ] && grep -q '^  max_step: 5.0e-3$' "$out/sync-3d-preview.yaml" \
  && grep -q 'tolerance: {position: 1.0e-4, angle: 1.0e-4}' "$out/sync-3d-preview.yaml" || { echo "FAIL  could not derive the preview scene"; exit 1; }
"$bin" run "$out/sync-3d-preview.yaml" -o "$out/sync-3d-preview" --force --no-animation > "$out/sync-3d-preview.log" 2>&1 \
  || { cat "$out/sync-3d-preview.log"; exit 1; }
/usr/bin/python3 "$root/tests/apps/check_demo.py" "$out" "$out/sync-beam-stiff-cables" "$out/sync-3d-preview"

pvd="$out/sync-3d/animation.pvd"
png="$out/sync-3d/render.png"
log="$("$root/scripts/pvrender.sh" "$pvd" "$png" 2>&1)" || { echo "$log"; echo "FAIL  ParaView could not render $pvd"; exit 1; }
echo "$log" | tail -3
cards() { grep -cE "^($2)[ *]" "$root/meshes/$1.bdf" || true; }
points=$(( $(cards yoke GRID) + 2 * $(cards panel GRID) ))
cells=$(( $(cards yoke 'CBAR|CBEAM|CROD|CQUAD4|CTRIA3') + 2 * $(cards panel 'CBAR|CBEAM|CROD|CQUAD4|CTRIA3') ))
steps=$(grep -c '<DataSet' "$pvd")
echo "$log" | grep -q "points=$points cells=$cells steps=" || { echo "FAIL  ParaView read other than points=$points cells=$cells"; exit 1; }
size=$(stat -c %s "$png")
[ "$(head -c 4 "$png" | tail -c 3)" = PNG ] && [ "$size" -gt 2000 ] || { echo "FAIL  $png is not a rendered PNG"; exit 1; }
echo "ok    ParaView rendered $pvd ($points points, $cells cells, $steps data sets) to $png ($size bytes)"
