#!/usr/bin/env bash
# The remesh_conformal tool on every mesh of CGAL's public data (the .off files of
# .cache/cgal-data/data/meshes, fetched by scripts/fetch_cgal_data.sh), at its defaults: which
# models are remeshed, with what quality, and which are refused and why. Each model runs in its
# own process with a time limit; a crash or a hang is recorded as such, not hidden.
#
#   bash benchmark/Conformal_remeshing/run_cgal_data_sweep.sh [--time-limit SECONDS]
#        [--models NAME,...] [--largest N] [OUT_DIR]
#
#   --time-limit  seconds per model; the tool stops itself (exit code 3) and is killed a minute
#                 later if it does not [120]
#   --models      only these models (file names without .off, e.g. cheese,blade)
#   --largest     skip models with more than N input vertices [200000]
#   OUT_DIR       where the results go [out/cgal_data_sweep]
#
# Environment: BUILD_DIR (Release build directory, default build/benchmark), JOBS (parallel
# compile jobs, default nproc).
#
# OUT_DIR/summary.md holds the table (one row per model: the outcome, the output's size and
# quality as the tool prints them, or the tool's message), OUT_DIR/summary.json the same rows,
# OUT_DIR/runs/<model>.log the tool's output (its summary and messages) and <model>.json its
# report. Exit code 0 when every model was remeshed or refused with a clear message (exit code 1
# of the tool: an input it cannot remesh), 1 when one crashed, hung, ran out of time or failed
# otherwise, 2 on a usage or set-up error.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
fail() { echo "run_cgal_data_sweep.sh: $*" >&2; exit 2; }

time_limit=120 models="" largest=200000 out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --time-limit) [ $# -ge 2 ] || fail "--time-limit needs a value"; time_limit="$2"; shift 2 ;;
    --models) [ $# -ge 2 ] || fail "--models needs a value"; models="$2"; shift 2 ;;
    --largest) [ $# -ge 2 ] || fail "--largest needs a value"; largest="$2"; shift 2 ;;
    -h|--help) sed -n '2,24p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) fail "unknown option '$1' (see --help)" ;;
    *) [ -z "$out" ] || fail "unexpected argument '$1'"; out="$1"; shift ;;
  esac
done
[[ "$time_limit" =~ ^[0-9]+$ ]] && [ "$time_limit" -gt 0 ] || fail "--time-limit must be a positive number of seconds"
[[ "$largest" =~ ^[0-9]+$ ]] || fail "--largest must be a number of vertices"
out="${out:-$root/out/cgal_data_sweep}"
build="${BUILD_DIR:-$root/build/benchmark}"

# --- build (Release) and data ---------------------------------------------------------------------
bash "$root/scripts/install_dependencies.sh"
bash "$root/scripts/fetch_cgal_data.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DCGAL_CONFORMAL_REMESHING_BUILD_EXAMPLES=ON >/dev/null
cmake --build "$build" --target remesh_conformal_tool -j "${JOBS:-$(nproc)}"
tool="$build/examples/Conformal_remeshing/remesh_conformal"
data="$root/.cache/cgal-data/data/meshes"

# --- the runs -------------------------------------------------------------------------------------
mkdir -p "$out/runs"
if [ -n "$models" ]; then
  IFS=, read -r -a names <<< "$models"
  files=()
  for name in "${names[@]}"; do
    [ -f "$data/$name.off" ] || fail "no model $data/$name.off"
    files+=("$data/$name.off")
  done
else
  mapfile -t files < <(ls "$data"/*.off)
fi

# JSON string escaping for the messages.
json_string() { printf '"%s"' "$(printf '%s' "$1" | sed 's/\\/\\\\/g; s/"/\\"/g' | tr -d '\000-\037')"; }
# The first number after `label` in the tool's summary lines.
number_after() { sed -n "s/.*$1 \([-0-9.e+]*\).*/\1/p" "$2" | head -n 1; }

rows=() json_rows=() troubles=()
count=0 remeshed=0 refused=0
total=${#files[@]}
echo "CGAL data sweep: $total models, at most $time_limit s each; results in $out"
for file in "${files[@]}"; do
  name="$(basename "$file" .off)"
  count=$((count + 1))
  vertices=$(awk 'NR == 1 && $1 != "OFF" { print "?"; exit } NR == 1 && NF > 1 { print $2; exit } NR == 2 { print $1; exit }' "$file")
  [[ "$vertices" =~ ^[0-9]+$ ]] || vertices=null # a header this does not read: the tool will say
  if [ "$vertices" != null ] && [ "$vertices" -gt "$largest" ]; then
    echo "[$count/$total] $name: $vertices vertices, above --largest $largest: skipped"
    rows+=("| $name | $vertices | skipped (above --largest) | | | | | | |")
    json_rows+=("{\"model\": $(json_string "$name"), \"input_vertices\": $vertices, \"outcome\": \"skipped\"}")
    continue
  fi
  log="$out/runs/$name.log" report="$out/runs/$name.json" output="$out/runs/$name.out.off"
  rm -f "$log" "$report" "$output"
  start=$(date +%s.%N)
  status=0
  timeout --kill-after=10 $((time_limit + 60)) \
    "$tool" "$file" "$output" --report "$report" --time-limit "$time_limit" </dev/null > "$log" 2>&1 || status=$?
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  # The meshes themselves are not kept (a full sweep would fill gigabytes), only their checksum,
  # so that two sweeps can be compared byte for byte.
  checksum=null
  [ ! -f "$output" ] || checksum="\"$(sha256sum "$output" | cut -c1-64)\""
  rm -f "$output"
  case "$status" in
    0) outcome=remeshed; remeshed=$((remeshed + 1)) ;;
    1) outcome=refused; refused=$((refused + 1)) ;;
    3) outcome="time limit" ;;
    124|137) outcome="killed (hang)" ;;
    *) outcome="failed (exit $status)" ;;
  esac
  if [ "$status" -eq 0 ]; then
    out_vertices=$(sed -n 's/.*: \([0-9]*\) vertices, [0-9]* faces.*/\1/p' "$log" | head -n 1)
    min_angle=$(number_after "minimum angle" "$log")
    input_angle=$(sed -n 's/.*minimum angle [-0-9.e+]* deg (input \([-0-9.e+]*\)).*/\1/p' "$log" | head -n 1)
    below=$(sed -n 's/.*, \([-0-9.e+]*\)% of triangles below 25 deg.*/\1/p' "$log" | head -n 1)
    below_elsewhere=$(sed -n 's/.*% of triangles below 25 deg (\([-0-9.e+]*\)% away from .*/\1/p' "$log" | head -n 1)
    skewness=$(number_after "mean skewness" "$log")
    to=$(sed -n 's/.*Hausdorff distance to \/ from the input: \([-0-9.e+]*\) \/ .*/\1/p' "$log" | head -n 1)
    from=$(sed -n 's/.*Hausdorff distance to \/ from the input: [-0-9.e+]* \/ \([-0-9.e+]*\) x diagonal.*/\1/p' "$log" | head -n 1)
    intersections=$(sed -n 's/.*self-intersections: \([A-Za-z0-9 ]*\).*/\1/p' "$log" | head -n 1)
    rows+=("| $name | $vertices | $outcome | $seconds | $out_vertices | $min_angle ($input_angle) | $below ($below_elsewhere) | $skewness | $to / $from, self-intersections: $intersections |")
    json_rows+=("{\"model\": $(json_string "$name"), \"input_vertices\": $vertices, \"outcome\": \"$outcome\", \"seconds\": $seconds, \"output_vertices\": ${out_vertices:-null}, \"minimum_angle\": ${min_angle:-null}, \"input_minimum_angle\": ${input_angle:-null}, \"percent_below_25\": ${below:-null}, \"percent_below_25_away_from_sharp_corners\": ${below_elsewhere:-null}, \"mean_skewness\": ${skewness:-null}, \"hausdorff_to_input\": ${to:-null}, \"hausdorff_from_input\": ${from:-null}, \"self_intersections\": $(json_string "$intersections"), \"output_sha256\": $checksum}")
    echo "[$count/$total] $name: remeshed in $seconds s, $out_vertices vertices, smallest angle $min_angle (input $input_angle)"
  else
    message="$(grep -v '^remesh_conformal: [a-z ]*$' "$log" | tail -n 1 | cut -c1-400)"
    [ -n "$message" ] || message="(no message)"
    rows+=("| $name | $vertices | $outcome | $seconds | | | | | ${message//|/\\|} |")
    json_rows+=("{\"model\": $(json_string "$name"), \"input_vertices\": $vertices, \"outcome\": \"$outcome\", \"seconds\": $seconds, \"message\": $(json_string "$message")}")
    echo "[$count/$total] $name: $outcome in $seconds s: $message"
    [ "$status" -eq 1 ] || troubles+=("$name: $outcome: $message")
  fi
done

# --- the tables -------------------------------------------------------------------------------------
{
  echo "# remesh_conformal on CGAL's data meshes"
  echo
  echo "Defaults (target edge length 1% of the diagonal), at most $time_limit s per model. $remeshed of $total"
  echo "remeshed, $refused refused with a message, ${#troubles[@]} crashed, hung or ran out of time."
  echo "Angles in degrees (the input's smallest in parentheses); below 25: share of triangles in %, and"
  echo "in parentheses the share whose smallest angle is not at an input corner sharper than 25 degrees;"
  echo "Hausdorff distances to / from the input over its diagonal."
  echo
  echo "| model | input vertices | outcome | seconds | output vertices | smallest angle | below 25 | mean skewness | Hausdorff, or the tool's message |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  printf '%s\n' "${rows[@]}"
} > "$out/summary.md"
{
  echo "{\"time_limit\": $time_limit, \"models\": ["
  for i in "${!json_rows[@]}"; do
    [ "$i" -eq 0 ] || echo ","
    printf '  %s' "${json_rows[$i]}"
  done
  echo
  echo "]}"
} > "$out/summary.json"
echo
echo "$remeshed of $total remeshed, $refused refused with a message; tables: $out/summary.md and summary.json"
if [ ${#troubles[@]} -gt 0 ]; then
  echo "run_cgal_data_sweep.sh: ${#troubles[@]} models crashed, hung or ran out of time:" >&2
  printf '  %s\n' "${troubles[@]}" >&2
  exit 1
fi
