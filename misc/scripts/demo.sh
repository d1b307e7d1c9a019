#!/usr/bin/env bash
# The README's main command: install what is missing, build, render the embedded demo scene.
# Writes out/demo.exr (scene-linear HDR) and out/demo.png (tonemapped preview), then the same room with
# each AreaLight3D replaced by a SpotLight3D of equal power (out/demo_punctual.exr/.png) and both side by
# side (out/demo_side_by_side.png); prints per-pass GPU times of both and the render's wall time.
# Extra arguments go to `godot-area render` (e.g. --width 1280 --height 720).
set -euo pipefail
cd "$(dirname "$0")/../.."
./misc/scripts/install_deps.sh
JOBS="$(nproc 2>/dev/null || echo 2)"
# Only what the demo runs: the engine and bin/godot-area (test.sh builds the tests and the Python module).
scons -Q -j"$JOBS" target=release bin/godot-area
mkdir -p out
TIMEFORMAT='demo: render took %R s wall clock (%U s user CPU)'
time ./bin/godot-area render -o out/demo.exr --png out/demo.png --compare-punctual "$@"
