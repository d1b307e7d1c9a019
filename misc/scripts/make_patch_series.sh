#!/usr/bin/env bash
# Writes the curated area-light patch series against patches/BASE into patches/series/ (committed):
# patches/manifest.txt lists each patch (subject, body, the paths and hunks it brings from BASE to the
# tree's state); patches/series_tool.py turns it into commits on a private index (fixed author and
# dates, so the output is byte-identical for the same tree) and `git format-patch` writes them as
# patches/series/<n>-<series>/NNNN-*.patch with patches/series/INDEX (application order and sizes).
# Never edit a patch by hand: change the tree or the manifest, then run this again.
#   ./misc/scripts/make_patch_series.sh [--target REV] [OUT_DIR]      (default HEAD, patches/series)
set -euo pipefail
cd "$(dirname "$0")/../.."
target=HEAD
if [ "${1:-}" = "--target" ]; then
	target="$2"
	shift 2
fi
out="${1:-patches/series}"
# Refuse to write a series that leaves a tree file behind or names a missing one.
python3 patches/series_tool.py check --target "$target" >/dev/null || [ $? = 3 ]
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 patches/series_tool.py write "$tmp" --target "$target" >/dev/null
rm -rf "$out"
mkdir -p "$(dirname "$out")"
mv "$tmp" "$out"
trap - EXIT
chmod 755 "$out"
echo "wrote $(grep -c '\.patch ' "$out/INDEX") patches against $(cut -c1-12 patches/BASE) to $out (largest: $(grep '^largest' "$out/INDEX" | cut -d' ' -f2-))"
