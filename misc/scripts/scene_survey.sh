#!/bin/sh
# Compatibility survey over public Godot 4 scenes (issue 15; results in doc/compatibility.md).
# usage: misc/scripts/scene_survey.sh MIRROR_GIT_DIR [SUBDIR=3d] [WORK=/tmp/scene_survey]
# Extracts SUBDIR of the mirror's HEAD (blobs absent from the mirror are skipped and counted),
# renders every format=3 3D scene with bin/godot-area at 160x90 (bounded by timeout), then loads
# and saves each through the Python module and counts original lines missing from the save.
# Prints one markdown table row per scene: | scene | status | warnings | lost lines | kept as placeholders |
set -u
MIRROR=$1
SUB=${2:-3d}
WORK=${3:-/tmp/scene_survey}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BIN=${GODOT_AREA_BIN:-$ROOT/bin/godot-area}
PYDIR=${GODOT_AREA_PYTHONPATH:-$ROOT/bin/python}
rm -rf "$WORK" && mkdir -p "$WORK/src" "$WORK/out"
absent=0
git --git-dir="$MIRROR" ls-tree -r HEAD "$SUB" | while read -r mode type sha path; do
	mkdir -p "$WORK/src/$(dirname "$path")"
	git --git-dir="$MIRROR" cat-file blob "$sha" > "$WORK/src/$path" 2>/dev/null || { rm -f "$WORK/src/$path"; echo "$path" >> "$WORK/absent.txt"; }
done
echo "commit $(git --git-dir="$MIRROR" rev-parse HEAD); blobs absent from the mirror: $(cat "$WORK/absent.txt" 2>/dev/null | wc -l)" >&2
cd "$WORK/src"
find "$SUB" -name '*.tscn' | sort | while read -r scene; do
	head -1 "$scene" | grep -q 'format=3' || continue
	grep -q 'type="\(Node3D\|MeshInstance3D\|Camera3D\|DirectionalLight3D\|OmniLight3D\|SpotLight3D\|WorldEnvironment\|CSG[A-Za-z]*3D\|StaticBody3D\|RigidBody3D\|CharacterBody3D\|Area3D\)"' "$scene" || continue
	base=$WORK/out/$(echo "$scene" | tr '/' '_')
	timeout 120 "$BIN" render "$scene" -o "$base.exr" --width 160 --height 90 > "$base.log" 2>&1
	rc=$?
	case $rc in
		0) status=ok ;;
		124) status=hang ;;
		2) if grep -q 'has no Camera3D' "$base.log"; then status="loaded (no Camera3D: nothing to render)"; else status="load failure: $(grep -m1 -o 'cannot load scene.*' "$base.log" | cut -c1-120)"; fi ;;
		*) if [ $rc -gt 128 ]; then status="crash ($rc)"; else status="failed ($rc): $(grep -m1 -v '^ *at:' "$base.log" | cut -c1-100)"; fi ;;
	esac
	warnings=$(grep -c '^WARNING' "$base.log")
	placeholders=$(grep -o 'Unknown node type "[A-Za-z0-9]*"' "$base.log" | sed 's/.*"\(.*\)"/\1/' | sort -u | tr '\n' ' ')
	lost=$(PYTHONPATH="$PYDIR" timeout 120 /usr/bin/python3 -c '
import sys, collections, godot_area as ga
src, out = sys.argv[1], sys.argv[2]
ga.save_scene(ga.load_scene(src), out)
a = collections.Counter(l.strip() for l in open(src) if l.strip())
b = collections.Counter(l.strip() for l in open(out) if l.strip())
print(sum((a - b).values()))' "$scene" "$base.saved.tscn" 2>/dev/null || echo "error")
	echo "| $scene | $status | $warnings | $lost | $placeholders |"
done
