#!/usr/bin/env bash
# Writes the area-light feature as a reviewable patch series against patches/BASE (the engine foundation
# without area-light code): one patch per commit, in order, under patches/series/ (not committed; generated).
#   ./misc/scripts/make_patch_series.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
base="$(cat patches/BASE)"
out="${1:-patches/series}"
rm -rf "$out"
mkdir -p "$out"
git format-patch --quiet --binary -o "$out" "$base..HEAD"
echo "wrote $(ls "$out" | wc -l) patches against ${base:0:12} to $out"
git log --reverse --format='%h %s' "$base..HEAD" | cut -c1-140
