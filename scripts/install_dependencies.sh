#!/usr/bin/env bash
# Installs what the project needs from Debian's packages; only what is missing, so running it
# again is quick and changes nothing. Works as root or through sudo.
#
#   scripts/install_dependencies.sh          to build the package, its tools (OpenMPI for
#                                            remesh_conformal_mpi) and its Python module (pybind11,
#                                            NumPy and the Python headers)
#   scripts/install_dependencies.sh --tests  also what the test suite needs: GoogleTest, doxygen,
#                                            pytest and CGAL's public test meshes (see fetch_cgal_data.sh)
#   scripts/install_dependencies.sh --robustness
#                                            also what the sanitizer tests and the fuzzers need:
#                                            Ninja, clang and its fuzzer and sanitizer runtimes
#   scripts/install_dependencies.sh --benchmarks
#                                            also the remeshing benchmark's external peers: Gmsh,
#                                            MeshLab (meshlabserver) and the X server it runs under
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

with_tests=0
with_robustness=0
with_benchmarks=0
for arg in "$@"; do
  case "$arg" in
    --tests) with_tests=1 ;;
    --robustness) with_robustness=1 ;;
    --benchmarks) with_benchmarks=1 ;;
    -h|--help) sed -n '2,15p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "install_dependencies.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

packages=(cmake make g++ libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev
          pybind11-dev python3-dev python3-numpy libopenmpi-dev openmpi-bin)
if [ "$with_tests" -eq 1 ]; then
  packages+=(libgtest-dev doxygen python3-pytest)
fi
if [ "$with_robustness" -eq 1 ]; then
  packages+=(ninja-build clang libclang-rt-14-dev)
fi
if [ "$with_benchmarks" -eq 1 ]; then
  packages+=(gmsh meshlab xvfb xauth)
fi

as_root() {
  if [ "$(id -u)" -eq 0 ]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "install_dependencies.sh: installing needs root or sudo: $*" >&2
    exit 1
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "Debian packages: all ${#packages[@]} present"
fi

if [ "$with_tests" -eq 1 ]; then
  bash "$root/scripts/fetch_cgal_data.sh"
fi
