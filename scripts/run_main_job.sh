#!/usr/bin/env bash
# The main job: installs what is needed, builds the tools (Release) and runs them on the shipped
# default model (or on the mesh file given as argument), writing the results under out/.
#
#   scripts/run_main_job.sh [MESH_FILE]
#
# The main job remeshes the model end to end with the default options (segmentation, welding,
# Ricci flow, planar meshing, pull-back, gluing) and reports the input's checks and the quality
# before and after (text, JSON and Fig. 10-style SVG histograms).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
model="${1:-examples/Conformal_remeshing/data/perforated_plate.off}"
if [ ! -f "$model" ]; then
  echo "run_main_job.sh: no such mesh file: $model" >&2
  exit 2
fi

bash scripts/install_dependencies.sh
build="$root/build/release"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
      -DCGAL_CONFORMAL_REMESHING_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" --target mesh_report remesh_conformal_tool -j"$(nproc)"

mkdir -p out
name="$(basename "${model%.*}")"
status=0
"$build/examples/Conformal_remeshing/mesh_report" "$model" \
    --json "out/${name}_report.json" --svg "out/${name}_quality.svg" | tee "out/${name}_report.txt" || status=$?
if [ "$status" -eq 0 ]; then
  echo
  mkdir -p "out/${name}_plots"
  "$build/examples/Conformal_remeshing/remesh_conformal" "$model" "out/${name}_remeshed.off" \
      --report "out/${name}_remeshing.json" --plots "out/${name}_plots" | tee "out/${name}_remeshing.txt" || status=$?
fi
echo
echo "Results for $model are in $root/out/:"
echo "  ${name}_report.txt       the input's checks, topology and quality (printed above)"
echo "  ${name}_report.json      the full input report (checks, topology, quality, histograms)"
echo "  ${name}_quality.svg      the input's angle and skewness histograms (open it in a browser)"
echo "  ${name}_remeshed.off     the remeshed surface"
echo "  ${name}_remeshing.txt    the remeshing summary (printed above)"
echo "  ${name}_remeshing.json   stage times, segmentation, flattening, quality before and after, fidelity"
echo "  ${name}_plots/quality.svg  histograms before and after remeshing"
exit "$status"
