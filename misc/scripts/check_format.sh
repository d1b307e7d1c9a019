#!/usr/bin/env bash
# Format check of the C++ sources against .clang-format (Godot's style), a clang-format dry run.
#
#   misc/scripts/check_format.sh            report: lists the files clang-format would change, exits 0
#   misc/scripts/check_format.sh --strict   the same, exits 1 when any file would change
#   misc/scripts/check_format.sh --base REV only the files changed since REV (git diff REV --name-only)
#
# CI (.ci/run) runs --strict over every file: run `--strict --base main` before a commit (or
# `clang-format -i FILE` on what it names). Without clang-format it says so and exits 0.
set -euo pipefail
cd "$(dirname "$0")/../.."
strict=0
base=""
while [ $# -gt 0 ]; do
	case "$1" in
		--strict) strict=1 ;;
		--base) base="$2"; shift ;;
		*) echo "check_format.sh: unknown argument '$1'" >&2; exit 2 ;;
	esac
	shift
done
if ! command -v clang-format > /dev/null; then
	echo "check_format.sh: clang-format is not installed; format not checked."
	exit 0
fi
if [ -n "$base" ]; then
	files=$(git diff --name-only --diff-filter=d "$base" -- '*.cpp' '*.h')
else
	files=$(git ls-files '*.cpp' '*.h')
fi
total=0
bad=0
for f in $files; do
	total=$((total + 1))
	if ! clang-format --dry-run -Werror "$f" > /dev/null 2>&1; then
		bad=$((bad + 1))
		echo "format: $f differs from .clang-format (clang-format -i $f)"
	fi
done
echo "format: $bad of $total files differ from .clang-format"
if [ "$strict" = 1 ] && [ "$bad" -gt 0 ]; then
	exit 1
fi
exit 0
