#!/usr/bin/env bash
# Installs what the tests need, builds everything (the Python module too) and runs the whole test
# suite through CTest, the module's pytest suite included (python/tests).
# Exits non-zero when any test fails. Tests are built with -O1 but without NDEBUG, so CGAL's
# own assertions stay active. -O1 rather than -O2: the build is most of CI's time, and on the
# 2-core machine test_remeshing.cpp compiled in 173 s instead of 249 s while its tests ran in
# 20.2 s instead of 19.4 s. The benchmark programs the tests do not run are left
# out of the build (benchmark/Conformal_remeshing/CMakeLists.txt); build them with the
# benchmarks' scripts, in a Release build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/install_dependencies.sh --tests
build="$root/build/tests"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1" \
      -DCGAL_CONFORMAL_REMESHING_REQUIRE_ALL_TESTS=ON -DCGAL_CONFORMAL_REMESHING_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 1200
