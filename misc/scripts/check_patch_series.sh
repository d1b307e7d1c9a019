#!/usr/bin/env bash
# Checks the committed patch series (patches/series/, written by make_patch_series.sh from
# patches/manifest.txt) against the tree:
#   1. every path changed since patches/BASE is carried by a patch or excluded by name in the manifest
#      (results, images, binaries, patches/ itself), so a new file cannot silently fall out; every
#      quoted #include resolves after each patch (a cheap stand-in for "each step builds");
#   2. the committed series is what the generator writes for this tree (not stale, not hand-edited);
#   3. the series applies with `git apply` to BASE in a temporary worktree, and the result equals the
#      tree for every carried path.
# With --each, after every patch it also builds (scons -j2 target=release) and runs the doctest files
# the patch adds or changes; with --compile it compiles (objects only) the .cpp files the patch changes,
# with --includers also those that include a header it changes; --from N / --to N limit that to patches
# N..M (1-based, INDEX order).
#   ./misc/scripts/check_patch_series.sh [--each|--compile [--includers]] [--from N] [--to M] [--keep]
# Prints one summary line last ("patch series: ..."); exit status 0 when everything holds.
set -euo pipefail
cd "$(dirname "$0")/../.."
root="$PWD"
each=0
from=1
to=100000
keep=0
includers=0
while [ $# -gt 0 ]; do
	case "$1" in
		--each) each=1 ;;
		--compile) each=2 ;;
		--includers) includers=1 ;;
		--from) from="$2"; shift ;;
		--to) to="$2"; shift ;;
		--keep) keep=1 ;;
		*) echo "usage: $0 [--each|--compile [--includers] [--from N] [--to M]] [--keep]" >&2; exit 2 ;;
	esac
	shift
done
base="$(cat patches/BASE)"
series=patches/series
start=$(date +%s)
fail=0

# 1. Assignment and includes.
if ! python3 patches/series_tool.py check; then
	fail=1
fi

# 2. The committed series is the generator's output for this tree.
tmp="$(mktemp -d)"
wt="$tmp/worktree"
cleanup() {
	if [ -d "$wt" ]; then
		git worktree remove --force "$wt" >/dev/null 2>&1 || true
	fi
	if [ "$keep" = 0 ]; then
		rm -rf "$tmp"
	else
		echo "kept $tmp" >&2
	fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM
if [ ! -f "$series/INDEX" ]; then
	echo "no committed series: run ./misc/scripts/make_patch_series.sh" >&2
	exit 1
fi
python3 patches/series_tool.py write "$tmp/fresh" >/dev/null 2>&1 || true
if ! diff -r -q "$series" "$tmp/fresh" >"$tmp/stale.txt" 2>&1; then
	echo "stale series: patches/series differs from what make_patch_series.sh writes now:" >&2
	head -20 "$tmp/stale.txt" >&2
	fail=1
fi

# 3. Apply to BASE and compare with the tree.
git worktree add --quiet --detach "$wt" "$base"
if [ "$each" != 0 ] && [ -d build ]; then
	cp -a build "$wt/build"
fi
count=0
built=0
failed_steps=0
applied=0
while read -r name _; do
	case "$name" in *.patch) ;; *) continue ;; esac
	count=$((count + 1))
	if ! git -C "$wt" apply --index --whitespace=nowarn "$root/$series/$name"; then
		echo "does not apply to BASE + the patches before it: $series/$name" >&2
		fail=1
		break
	fi
	applied=$((applied + 1))
	if [ "$each" = 2 ] && [ "$count" -ge "$from" ] && [ "$count" -le "$to" ]; then
		t0=$(date +%s)
		sources=$(grep -E '^\+\+\+ b/.*\.cpp$' "$root/$series/$name" | sed 's|^+++ b/||' || true)
		if [ "$includers" = 1 ]; then
			# Also the .cpp files that include a header this patch changes (by its full path).
			for header in $(grep -E '^\+\+\+ b/.*\.(h|inc)$' "$root/$series/$name" | sed 's|^+++ b/||'); do
				sources="$sources
$(cd "$wt" && git grep -l -F "#include \"$header\"" -- '*.cpp' || true)"
			done
		fi
		objects=$(echo "$sources" | grep -v '^$' | sort -u | grep -v '^tests/fuzz/' | grep -v '^modules/python/godot_area_' | sed 's|^\(.*\)\.cpp$|build/release/\1.o|' || true)
		result="nothing to compile"
		if [ -n "$objects" ]; then
			# shellcheck disable=SC2086
			if (cd "$wt" && scons -Q -k -j2 target=release $objects >"$tmp/build_$count.log" 2>&1); then
				result="compiled $(echo "$objects" | wc -l) files"
			else
				echo "compile fails after $name (log: $tmp/build_$count.log):" >&2
				grep -E 'error' "$tmp/build_$count.log" | sort -u | head -12 >&2 || tail -5 "$tmp/build_$count.log" >&2
				fail=1
				keep=1
				failed_steps=$((failed_steps + 1))
				# The files whose own text fails (an error inside an included header names the header).
				result="COMPILE FAILS in $(grep -oE '^[^: ]+\.(cpp|h|inc):[0-9]+:[0-9]+: error' "$tmp/build_$count.log" | cut -d: -f1 | sed 's|^\./||' | sort -u | paste -sd' ' -)"
			fi
		fi
		built=$((built + 1))
		echo "after $name: $result ($(($(date +%s) - t0)) s)"
	fi
	if [ "$each" = 1 ] && [ "$count" -ge "$from" ] && [ "$count" -le "$to" ]; then
		t0=$(date +%s)
		if ! (cd "$wt" && scons -Q -j2 target=release >"$tmp/build_$count.log" 2>&1); then
			echo "build fails after $name (log: $tmp/build_$count.log; --keep keeps it):" >&2
			grep -m5 -E 'error|Error' "$tmp/build_$count.log" >&2 || tail -5 "$tmp/build_$count.log" >&2
			fail=1
			keep=1
			continue
		fi
		tests=$(grep -E '^\+\+\+ b/tests/.*\.cpp$' "$root/$series/$name" | sed 's|^+++ b/||' | sort -u | sed 's|.*/|*|' | paste -sd, - || true)
		result="built"
		if [ -n "$tests" ]; then
			if (cd "$wt" && GODOT_AREA_VALIDATION=1 GODOT_AREA_DEVICE=llvmpipe ./bin/godot-area-tests -sf="$tests" >"$tmp/test_$count.log" 2>&1); then
				result="built, $(grep -a '^\[doctest\] test cases' "$tmp/test_$count.log" | tail -1 || true)"
			else
				echo "tests fail after $name (-sf=$tests):" >&2
				grep -a -m10 -E 'ERROR|FAILED|error' "$tmp/test_$count.log" >&2 || true
				fail=1
				keep=1
				result="built, tests FAIL"
			fi
		fi
		built=$((built + 1))
		echo "after $name: $result ($(($(date +%s) - t0)) s)"
	fi
done <"$series/INDEX"
git -C "$wt" add -A >/dev/null
tree="$(git -C "$wt" write-tree)"
if ! python3 patches/series_tool.py compare "$tree"; then
	fail=1
fi
status="ok"
[ "$fail" = 0 ] || status="FAILED"
extra=""
[ "$each" = 1 ] && extra=", $built built and tested"
[ "$each" = 2 ] && extra=", $built compiled ($failed_steps failing)"
echo "patch series: $status: $applied of $count patches applied to ${base:0:12}, tree compared$extra ($(($(date +%s) - start)) s)"
exit "$fail"
