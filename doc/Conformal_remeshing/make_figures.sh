#!/usr/bin/env bash
# Regenerates every figure of the user manual into doc/Conformal_remeshing/fig/, from the
# package's own tools: it builds them (Release), generates the models, flattens and remeshes
# them, renders the meshes offscreen with render_mesh (a software rasterizer, no display
# needed) and converts the tools' SVG pictures to PNG with rsvg-convert (Debian's librsvg2-bin).
#
#   bash doc/Conformal_remeshing/make_figures.sh [--build DIR] [--jobs N] [--cgal-data DIR] [--no-brake]
#
#   --build DIR  build directory of the tools (default build/figures; one configured already is
#                used as it is); the intermediate meshes and pictures go to DIR/figure_work
#   --jobs N     parallel compile jobs (default 2)
#   --cgal-data DIR  CGAL's data folder, for the shark's pictures (default .cache/cgal-data/data,
#                see scripts/fetch_cgal_data.sh); without it those pictures are kept as they are
#   --no-brake   leave out the genus-83 brake disc (the slowest model), keeping its old pictures
#
# The figures are deterministic for a given build: the models come from fixed seeds and the
# tools are run with fixed options. The pictures are 450 x 450 or 600 x 450 pixels, the
# histograms 800 pixels wide.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build/figures
cgal_data=$root/.cache/cgal-data/data
jobs=2
brake=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --cgal-data) cgal_data=$2; shift 2 ;;
    --no-brake) brake=0; shift ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "make_figures.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

fig=$root/doc/Conformal_remeshing/fig
work=$build/figure_work
mkdir -p "$fig" "$work"

if ! command -v rsvg-convert > /dev/null; then
  echo "make_figures.sh: rsvg-convert is missing: apt-get install librsvg2-bin" >&2
  exit 2
fi

# --- the tools ----------------------------------------------------------------------------------
if [ ! -f "$build/CMakeCache.txt" ]; then # a build directory configured already keeps its settings
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF > "$work/cmake.log"
fi
nice cmake --build "$build" -j"$jobs" --target render_mesh conformal_flatten remesh_conformal_tool \
  generate_paper_model generate_cad_model > "$work/build.log"
tools=$build/examples/Conformal_remeshing
render=$tools/render_mesh
flatten=$tools/conformal_flatten
remesh=$tools/remesh_conformal
generate=$build/benchmark/Conformal_remeshing/generate_paper_model
generate_cad=$build/benchmark/Conformal_remeshing/generate_cad_model

# An SVG picture of the tools as a PNG of WIDTH x HEIGHT pixels: svg_to_png IN.svg OUT.png W H
svg_to_png() { rsvg-convert --width "$3" --height "$4" --keep-aspect-ratio --background-color white "$1" -o "$2"; }

# The plane through the middle of a model's bounding box in z, as a,b,c,d of --cut-plane (where
# the paper cuts its brake): mid_plane FILE.off
mid_plane() {
  awk 'NR == 1 { next } NR == 2 { n = $1; next } n > 0 && NF >= 3 {
         if(min == "" || $3 < min) min = $3; if(max == "" || $3 > max) max = $3; if(--n == 0) exit }
       END { printf "0,0,1,%.17g\n", -(min + max) / 2 }' "$1"
}

# The largest patch that remesh_conformal --save-patches wrote into DIR: largest_patch DIR
largest_patch() {
  local best="" most=0 count
  for p in "$1"/patch_*[0-9].off; do
    count=$(awk 'NR == 2 { print $1; exit }' "$p")
    if [ "$count" -gt "$most" ]; then most=$count; best=$p; fi
  done
  echo "$best"
}

# The input, the output with their edges, both with the triangles below 20 degrees in red:
# before_after NAME IN OUT [render_mesh options]
before_after() {
  local name=$1 input=$2 output=$3
  shift 3
  "$render" "$input" "$fig/${name}_input.png" --highlight-angle 20 "$@"
  "$render" "$output" "$fig/${name}_output.png" --highlight-angle 20 "$@"
}

echo "== the perforated plate (the default model): input, output, patches, planar meshing, sizing"
plate=$root/examples/Conformal_remeshing/data/perforated_plate.off
rm -rf "$work/plate_patches"
cp "$plate" "$work/perforated_plate.off"
# In the work directory, so that the histograms' legends name the files without their folders.
(cd "$work" && "$remesh" perforated_plate.off plate_remeshed.off --relative-edge-length 0.02 --quiet \
  --plots plate_plots --save-patches plate_patches --deviation-map plate_deviation > plate.txt)
cp "$work/plate_deviation_input.png" "$fig/plate_deviation_input.png"
before_after plate "$plate" "$work/plate_remeshed.off"
svg_to_png "$work/plate_plots/quality.svg" "$fig/plate_quality.png" 800 400
patches=("$work"/plate_patches/patch_*[0-9].off)
also=()
for p in "${patches[@]:1}"; do also+=(--also "$p"); done
"$render" "${patches[0]}" "$fig/plate_patches.png" "${also[@]}" --edge-width 0
# A close-up of a corner: the input, Delaunay refinement alone and frontal insertion without the
# optimization on the surface, and the default output.
closeup=(--zoom 3 --focus 45,28,6 --highlight-angle 30)
"$remesh" "$plate" "$work/plate_refinement.off" --relative-edge-length 0.02 --quiet --no-frontal \
  --optimization-rounds 0 > "$work/plate_refinement.txt"
"$remesh" "$plate" "$work/plate_frontal.off" --relative-edge-length 0.02 --quiet --optimization-rounds 0 \
  > "$work/plate_frontal.txt"
"$render" "$plate" "$fig/plate_closeup_input.png" "${closeup[@]}"
"$render" "$work/plate_refinement.off" "$fig/plate_closeup_refinement.png" "${closeup[@]}"
"$render" "$work/plate_frontal.off" "$fig/plate_closeup_frontal.png" "${closeup[@]}"
"$render" "$work/plate_remeshed.off" "$fig/plate_closeup_optimized.png" "${closeup[@]}"
"$remesh" "$plate" "$work/plate_chord.off" --relative-edge-length 0.02 --chord-error 0.02 --quiet \
  > "$work/plate_chord.txt"
"$render" "$work/plate_chord.off" "$fig/plate_chord_error.png"

echo "== the wavy C-shaped strip (the paper's Fig. 2): without welding, and welded"
"$generate_cad" wavy_c_strip "$work/strip.off" > /dev/null
"$flatten" "$work/strip.off" "$work/strip" --unwelded --picture-size 450 > "$work/strip.txt"
svg_to_png "$work/strip_unwelded.svg" "$fig/strip_unwelded.png" 450 450
svg_to_png "$work/strip_welded.svg" "$fig/strip_welded.png" 450 450
svg_to_png "$work/strip_checkerboard.svg" "$fig/strip_checkerboard.png" 450 450
cp "$work/strip_textured.png" "$fig/strip_textured.png"

fandisk=$cgal_data/meshes/fandisk.off
if [ -f "$fandisk" ]; then
  echo "== CGAL's fandisk.off: where the output strays from the input"
  "$remesh" "$fandisk" "$work/fandisk_remeshed.off" --quiet --deviation-map "$work/fandisk_deviation" > "$work/fandisk.txt"
  cp "$work/fandisk_deviation_input.png" "$fig/fandisk_deviation_input.png"
fi
shark=$cgal_data/meshes/mech-holes-shark.off
if [ -f "$shark" ]; then
  echo "== CGAL's mech-holes-shark.off: a patch with 4 boundary loops, welded"
  "$flatten" "$shark" "$work/shark" --picture-size 450 > "$work/shark.txt"
  svg_to_png "$work/shark_welded.svg" "$fig/shark_welded.png" 450 450
  svg_to_png "$work/shark_checkerboard.svg" "$fig/shark_checkerboard.png" 450 450
  cp "$work/shark_textured.png" "$fig/shark_textured.png"
else
  echo "== $shark not found (scripts/fetch_cgal_data.sh): the shark's pictures are kept"
fi

echo "== the suspension arm (the paper's Fig. 7 and 10): welded patch, checkerboard, input, output"
"$generate" suspension_arm 10k "$work/arm.off" > /dev/null
rm -rf "$work/arm_patches"
(cd "$work" && "$remesh" arm.off arm_remeshed.off --relative-edge-length 0.02 --quiet \
  --plots arm_plots --save-patches arm_patches > arm.txt)
arm_patch=$(largest_patch "$work/arm_patches")
"$flatten" "$arm_patch" "$work/arm_patch" --picture-size 450 > "$work/arm_patch.txt"
svg_to_png "$work/arm_patch_welded.svg" "$fig/arm_welded.png" 450 450
svg_to_png "$work/arm_patch_checkerboard.svg" "$fig/arm_domain.png" 450 450
cp "$work/arm_patch_textured.png" "$fig/arm_textured.png"
before_after arm "$work/arm.off" "$work/arm_remeshed.off" --edge-width 1
svg_to_png "$work/arm_plots/quality.svg" "$fig/arm_quality.png" 800 400

if [ "$brake" = 1 ]; then
  echo "== the genus-83 brake disc (the paper's Fig. 9): its upper half welded, input, output"
  "$generate" brake_disc_upper_half 20k "$work/brake_half.off" > /dev/null
  "$flatten" "$work/brake_half.off" "$work/brake_half" --picture-size 450 > "$work/brake_half.txt"
  svg_to_png "$work/brake_half_welded.svg" "$fig/brake_welded.png" 450 450
  svg_to_png "$work/brake_half_checkerboard.svg" "$fig/brake_domain.png" 450 450
  cp "$work/brake_half_textured.png" "$fig/brake_textured.png"
  "$generate" brake_disc 20k "$work/brake.off" > /dev/null
  "$remesh" "$work/brake.off" "$work/brake_remeshed.off" --relative-edge-length 0.01 \
    --cut-plane "$(mid_plane "$work/brake.off")" --quiet > "$work/brake.txt"
  before_after brake "$work/brake.off" "$work/brake_remeshed.off" --view -0.3,-0.6,-1 --edge-width 1 \
    --zoom 2.5 --focus 0,-125,28
  "$render" "$work/brake_remeshed.off" "$fig/brake_closeup_rim.png" --view 0.2,1,-0.35 --zoom 4 \
    --focus 0,-170,14 --edge-width 1
fi

echo "== written:"
ls -l "$fig"/*.png
