#!/usr/bin/env bash
# The README's main command: install what is missing, build, render the embedded demo scene.
# Writes out/demo.exr (scene-linear HDR) and out/demo.png (tonemapped preview), prints per-pass GPU times.
set -euo pipefail
cd "$(dirname "$0")/../.."
./misc/scripts/install_deps.sh
JOBS="$(nproc 2>/dev/null || echo 2)"
scons -Q -j"$JOBS" target=release
mkdir -p out
./bin/godot-area render -o out/demo.exr --png out/demo.png "$@"
