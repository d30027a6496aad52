#!/usr/bin/env bash
# Builds a subset of the test suite (test_input_checks, test_mesh_quality, test_verifier: the
# readers, the checks, the quality measures and the verifier) with AddressSanitizer and
# UndefinedBehaviorSanitizer in build/sanitizers, and runs it through CTest. Fails on any test
# failure and on any sanitizer report (a report stops the test that made it).
#
#   scripts/run_sanitizer_tests.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
case "${1:-}" in
  -h|--help) sed -n '2,7p' "${BASH_SOURCE[0]}"; exit 0 ;;
  '') ;;
  *) echo "run_sanitizer_tests.sh: unknown argument '$1'" >&2; exit 2 ;;
esac

# Ninja builds the three targets in parallel in one invocation (CMake's Makefiles build the
# goals of one `make` call one after the other).
bash scripts/install_dependencies.sh --tests --robustness
build="$root/build/sanitizers"
if [ -f "$build/CMakeCache.txt" ] && ! grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$build/CMakeCache.txt"; then
  rm -rf "$build" # made by another generator
fi
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# -O1 keeps the stacks readable and the run short; without NDEBUG, CGAL's assertions stay on.
# -g1 (function names and line tables, enough for the reports' backtraces) rather than -g: the
# verifier's test, which runs the whole pipeline, compiled in 326 s instead of 442 s (object
# 84 MB instead of 192 MB; two compilations side by side on the 2-core machine).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
      -DCMAKE_CXX_FLAGS="$sanitizers" -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" >/dev/null
cmake --build "$build" -j"$(nproc)" --target test_verifier test_input_checks test_mesh_quality

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
cd "$build"
# Only the GoogleTest cases of the executables built above are registered under names that
# start with a capital letter (Suite.Test); tool tests and unbuilt executables start lowercase.
ctest --output-on-failure -j"$(nproc)" --timeout 1200 --no-tests=error -R '^[A-Z]'
