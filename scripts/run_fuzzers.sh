#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (address and undefined-behaviour sanitizers)
# and runs each for SECONDS_PER_TARGET seconds (default 60), starting from its seed corpus in
# fuzz/corpus/<target>/. Fails on any crash, sanitizer report, time-out or broken invariant;
# the input that did it is kept as build/fuzz/<target>/crash-* (replay: build/fuzz/<target> FILE).
#
#   scripts/run_fuzzers.sh [SECONDS_PER_TARGET]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

seconds="${1:-60}"
case "$seconds" in
  -h|--help) sed -n '2,7p' "${BASH_SOURCE[0]}"; exit 0 ;;
  ''|*[!0-9]*) echo "run_fuzzers.sh: SECONDS_PER_TARGET must be a whole number, not '$seconds'" >&2; exit 2 ;;
esac

# clang and its runtime libraries (libFuzzer, sanitizers), on top of the build dependencies.
bash "$root/scripts/install_dependencies.sh" --robustness

build="$root/build/fuzz"
mkdir -p "$build"
targets=()
for source in "$root"/fuzz/*.cpp; do
  targets+=("$(basename "$source" .cpp)")
done

# Each target is one translation unit: build them side by side, rebuilding only those whose
# source or a package header changed.
builds=()
for target in "${targets[@]}"; do
  binary="$build/$target"
  source="$root/fuzz/$target.cpp"
  if [ ! -x "$binary" ] || [ -n "$(find "$source" "$root/fuzz/fuzz_support.h" "$root/include" -newer "$binary" -print -quit)" ]; then
    echo "Building $target"
    clang++ -std=c++17 -O1 -g -fno-omit-frame-pointer \
            -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
            -I"$root/include" -I/usr/include/eigen3 "$source" -o "$binary.part" -lgmp -lmpfr &
    builds+=("$!:$target")
  fi
done
for b in "${builds[@]}"; do
  if ! wait "${b%%:*}"; then
    echo "run_fuzzers.sh: building ${b#*:} failed" >&2
    exit 1
  fi
  mv "$build/${b#*:}.part" "$build/${b#*:}"
done

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
for target in "${targets[@]}"; do
  seeds="$root/fuzz/corpus/$target"
  work="$build/$target.corpus"   # grows while fuzzing; the committed seeds stay as they are
  mkdir -p "$work"
  echo "Fuzzing $target for ${seconds} s"
  scratch="$(mktemp -d)"
  if (cd "$build" && TMPDIR="$scratch" "./$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
        -max_len=8192 -print_final_stats=1 -artifact_prefix="$build/$target-" "$work" "$seeds" \
        >"$build/$target.log" 2>&1); then
    grep -E "^(stat::number_of_executed_units|Done)" "$build/$target.log" || true
  else
    echo "run_fuzzers.sh: $target FAILED (log: $build/$target.log):" >&2
    grep -E "ERROR|SUMMARY|fuzz_|Test unit written" "$build/$target.log" | head -20 >&2 || true
    status=1
  fi
  rm -rf "$scratch"
done
exit $status
