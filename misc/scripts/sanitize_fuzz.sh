#!/usr/bin/env bash
# CI's robustness job (doc/reliability.md): one clang build with ASan+UBSan and libFuzzer
# (`scons fuzz=yes`, a subset of the engine: core, drivers, servers, scene, modules/gltf), then
#  1. the unit tests that build into it (tests/core, tests/scene, the glTF tests) under the sanitizers,
#  2. each libFuzzer harness for FUZZ_SECONDS (default 45) from the committed seed corpus; with
#     FUZZ_RUNS=N instead, exactly N inputs from the fixed seed FUZZ_SEED (default 1): the same inputs on
#     every run, so a finding is reproducible and never fails an unrelated change at random (CI's form).
# Any sanitizer report, test failure or fuzzer crash fails the job. Prints the time of each step.
set -euo pipefail
cd "$(dirname "$0")/../.."
JOBS="$(nproc 2>/dev/null || echo 2)"
FUZZ_SECONDS="${FUZZ_SECONDS:-45}"
FUZZ_RUNS="${FUZZ_RUNS:-}"
FUZZ_SEED="${FUZZ_SEED:-1}"
step() { echo "sanitize_fuzz: $1: $(( $(date +%s) - T0 )) s"; T0=$(date +%s); }
T0=$(date +%s)

scons -Q -j"$JOBS" target=release fuzz=yes
step "sanitized build"

# Vulkan drivers and the loader leak by design at exit; leak checking covers the engine through the
# fuzzers' per-input runs instead. halt_on_error: the first report fails the job.
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:abort_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export GODOT_AREA_VALIDATION=1
export GODOT_AREA_DEVICE="${GODOT_AREA_DEVICE:-llvmpipe}"
./bin/godot-area-tests.fuzz
step "unit tests under ASan+UBSan"

if [ -n "$FUZZ_RUNS" ]; then
	budget=(-runs="$FUZZ_RUNS" -seed="$FUZZ_SEED")
	what="$FUZZ_RUNS inputs, seed $FUZZ_SEED"
else
	budget=(-max_total_time="$FUZZ_SECONDS")
	what="$FUZZ_SECONDS s"
fi
if [ -z "$FUZZ_RUNS" ] && [ "$FUZZ_SECONDS" = "0" ]; then
	echo "sanitize_fuzz: fuzzing skipped (FUZZ_SECONDS=0)"
	exit 0
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for harness in resource_format_text:tscn gltf_document:gltf; do
	name="${harness%%:*}"
	kind="${harness##*:}"
	# New inputs go to a scratch corpus; the committed seeds are read only.
	mkdir -p "$work/$kind"
	ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=1" \
		./bin/fuzz_"$name" "$work/$kind" "tests/fuzz/corpus/$kind" -dict="tests/fuzz/$kind.dict" \
		"${budget[@]}" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
		-artifact_prefix="$work/" > "$work/$name.log" 2>&1 || true
	grep -E "^(stat::number_of_executed_units|stat::average_exec_per_sec|Done|==[0-9]+==ERROR|SUMMARY)" "$work/$name.log" || true
	# A crash, leak, timeout or OOM: an artifact, or libFuzzer's own report (a deadly signal may leave none).
	if ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* >/dev/null 2>&1 || grep -qE "SUMMARY: |deadly signal|==[0-9]+==ERROR" "$work/$name.log"; then
		echo "sanitize_fuzz: fuzz_$name found a failing input:"
		ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null || true
		grep -E -A30 "==[0-9]+==ERROR|deadly signal" "$work/$name.log" | head -60 || true
		exit 1
	fi
	step "fuzz_$name ($what)"
done
