#!/bin/sh
# "Renders lit" survey over public Godot 4 scenes (issue 16; results in doc/compatibility.md).
# usage: misc/scripts/scene_lit_survey.sh MIRROR_GIT_DIR [SUBDIR=3d] [WORK=/tmp/scene_lit_survey] [LIMIT=0]
# Extracts SUBDIR of the mirror's HEAD (blobs absent from the mirror are skipped), renders every format=3
# scene with a Camera3D at 96x54 (bin/godot-area render --png, timeout 90 s each; LIMIT > 0 stops after
# that many rendered scenes), then misc/scripts/lit_survey_report.py classifies the previews
# (definition of "lit" there) and writes the montage. Prints the report's table.
set -u
MIRROR=$1
SUB=${2:-3d}
WORK=${3:-/tmp/scene_lit_survey}
LIMIT=${4:-0}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BIN=${GODOT_AREA_BIN:-$ROOT/bin/godot-area}
rm -rf "$WORK" && mkdir -p "$WORK/src" "$WORK/out"
git --git-dir="$MIRROR" ls-tree -r HEAD "$SUB" | while read -r mode type sha path; do
	mkdir -p "$WORK/src/$(dirname "$path")"
	git --git-dir="$MIRROR" cat-file blob "$sha" > "$WORK/src/$path" 2>/dev/null || rm -f "$WORK/src/$path"
done
echo "commit $(git --git-dir="$MIRROR" rev-parse HEAD)" > "$WORK/commit.txt"
cd "$WORK/src"
count=0
find "$SUB" -name '*.tscn' | sort | while read -r scene; do
	head -1 "$scene" | grep -q 'format=3' || continue
	grep -q 'type="Camera3D"' "$scene" || continue # Sub-scenes without a camera have nothing to render.
	base=$WORK/out/$(echo "$scene" | tr '/' '_' | sed 's/\.tscn$//')
	timeout 90 "$BIN" render "$scene" -o "$base.exr" --png "$base.png" --width 96 --height 54 > "$base.log" 2>&1
	echo "$scene $?" >> "$WORK/rc.txt"
	rm -f "$base.exr"
	count=$((count + 1))
	if [ "$LIMIT" -gt 0 ] && [ "$count" -ge "$LIMIT" ]; then
		break
	fi
done
/usr/bin/python3 "$ROOT/misc/scripts/lit_survey_report.py" "$WORK"
