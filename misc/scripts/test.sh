#!/usr/bin/env bash
# The README's test command: install what is missing, build, run every test with the
# Vulkan validation layer on (tests fail on any validation error).
set -euo pipefail
cd "$(dirname "$0")/../.."
./misc/scripts/install_deps.sh
JOBS="$(nproc 2>/dev/null || echo 2)"
scons -Q -j"$JOBS" target=release
export GODOT_AREA_VALIDATION=1
# lavapipe is the default device in tests (the default suite must not need a GPU).
export GODOT_AREA_DEVICE="${GODOT_AREA_DEVICE:-llvmpipe}"
./bin/godot-area-tests "$@"
