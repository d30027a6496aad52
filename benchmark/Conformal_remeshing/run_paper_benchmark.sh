#!/usr/bin/env bash
# The paper benchmark: the paper's Table 1 and Fig. 10 reproduced on the generated
# stand-ins of its five car parts, remesh_conformal() against CGAL's isotropic_remeshing() (and,
# when asked, Gmsh and MeshLab) in the same run, and the growth of every stage with the input size.
#
#   bash benchmark/Conformal_remeshing/run_paper_benchmark.sh [--scale full|small]
#        [--part table|scaling|all] [--models NAME,...] [--methods conformal,isotropic,gmsh,meshlab]
#        [--time-limit SECONDS] [--resume] [OUT_DIR]
#
#   --scale       full: Table 1's sizes (87k to 804k input vertices) and 10k to 1M for the growth
#                 (hours on 2 cores); small: a tenth of Table 1's sizes and 10k to 100k (minutes)
#                 [full]
#   --part        Table 1 runs, growth runs or both [all]
#   --models      only these parts (generator names, e.g. suspension_arm,brake_disc)
#   --methods     these remeshers (conformal: ours; isotropic: CGAL's isotropic_remeshing(); gmsh,
#                 meshlab: the peers outside CGAL, installed by the script when listed)
#                 [conformal,isotropic]
#   --time-limit  seconds per run before it is stopped and recorded as such [3600 full, 900 small]
#   --resume      keep the runs already recorded as finished in OUT_DIR
#   OUT_DIR       where the results go [out/paper_benchmark_<scale>]
#
# Environment: BUILD_DIR (Release build directory, default build/benchmark), MODEL_CACHE
# (generated models, default .cache/paper_models), JOBS (parallel compile jobs, default nproc).
#
# Each run is its own process (paper_benchmark run), so its peak memory is its own; its record is
# OUT_DIR/runs/<id>.json (with .log and .exit). OUT_DIR/summary.md and summary.json hold the
# tables, OUT_DIR/fig10_*.svg the histograms. Exit code 0 when every run finished, 1 when one did
# not (the summary says which and why), 2 on a usage or set-up error.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
fail() { echo "run_paper_benchmark.sh: $*" >&2; exit 2; }
trap 'echo "run_paper_benchmark.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR

scale=full part=all models="" methods="" time_limit="" resume=0 out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --scale) [ $# -ge 2 ] || fail "--scale needs a value"; scale="$2"; shift 2 ;;
    --part) [ $# -ge 2 ] || fail "--part needs a value"; part="$2"; shift 2 ;;
    --models) [ $# -ge 2 ] || fail "--models needs a value"; models="$2"; shift 2 ;;
    --methods) [ $# -ge 2 ] || fail "--methods needs a value"; methods="$2"; shift 2 ;;
    --time-limit) [ $# -ge 2 ] || fail "--time-limit needs a value"; time_limit="$2"; shift 2 ;;
    --resume) resume=1; shift ;;
    -h|--help) sed -n '2,28p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) fail "unknown option '$1' (see --help)" ;;
    *) [ -z "$out" ] || fail "unexpected argument '$1'"; out="$1"; shift ;;
  esac
done
case "$scale" in full|small) ;; *) fail "--scale must be full or small, not '$scale'" ;; esac
case "$part" in table|scaling|all) ;; *) fail "--part must be table, scaling or all, not '$part'" ;; esac
[ -n "$time_limit" ] || time_limit=$([ "$scale" = full ] && echo 3600 || echo 900)
[[ "$time_limit" =~ ^[0-9]+$ ]] && [ "$time_limit" -gt 0 ] || fail "--time-limit must be a positive number of seconds"
out="${out:-$root/out/paper_benchmark_$scale}"
build="${BUILD_DIR:-$root/build/benchmark}"
cache="${MODEL_CACHE:-$root/.cache/paper_models}"

# --- build (Release) --------------------------------------------------------------------------
case ",$methods," in
  *,gmsh,*|*,meshlab,*) bash "$root/scripts/install_dependencies.sh" --benchmarks ;;
  *) bash "$root/scripts/install_dependencies.sh" ;;
esac
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >/dev/null
cmake --build "$build" --target generate_paper_model paper_benchmark paper_benchmark_summary \
      -j "${JOBS:-$(nproc)}"
bin="$build/benchmark/Conformal_remeshing"

# --- the runs -----------------------------------------------------------------------------------
mkdir -p "$out/runs" "$cache"
# Cached models are named after the generators' sources too: a changed generator makes new ones.
generator_key=$(cat "$root"/generators/Conformal_remeshing/*.h | sha1sum | cut -c1-10)
plan_args=(--scale "$scale" --part "$part")
[ -z "$models" ] || plan_args+=(--models "$models")
[ -z "$methods" ] || plan_args+=(--methods "$methods")
plan="$("$bin/paper_benchmark" plan "${plan_args[@]}")"
[ -n "$plan" ] || fail "no run matches --part $part --models '$models' --methods '$methods'"
total=$(printf '%s\n' "$plan" | wc -l)
echo "Paper benchmark, $scale scale: $total runs, at most $time_limit s each; results in $out"
index=0 unfinished=()
while read -r id model vertices method output_vertices cut; do
  index=$((index + 1))
  record="$out/runs/$id.json"
  if [ "$resume" -eq 1 ] && grep -qs '"status": "ok"' "$record"; then
    echo "[$index/$total] $id: recorded already (--resume)"
    continue
  fi
  mesh="$cache/${model}_${vertices}_${generator_key}.off"
  if [ ! -s "$mesh" ]; then
    echo "[$index/$total] generating $model with $vertices vertices"
    "$bin/generate_paper_model" "$model" "$vertices" "$mesh" --seed 1 \
      || fail "cannot generate $model with $vertices vertices into $mesh"
  fi
  args=(run "$mesh" "$record" --method "$method" --name "$model" --target-output-vertices "$output_vertices"
        --time-limit "$time_limit")
  [ "$cut" != cut ] || args+=(--mid-plane-cut)
  echo "[$index/$total] $id: $method on $model ($vertices vertices)"
  rm -f "$record" "$out/runs/$id.exit"
  status=0
  "$bin/paper_benchmark" "${args[@]}" </dev/null 2> "$out/runs/$id.log" || status=$?
  echo "$status" > "$out/runs/$id.exit"
  if [ "$status" -ne 0 ]; then
    unfinished+=("$id (exit status $status: $(tail -n 1 "$out/runs/$id.log"))")
    echo "    did not finish: $(tail -n 1 "$out/runs/$id.log")"
  else
    echo "    $(tail -n 1 "$out/runs/$id.log" | sed 's/^paper_benchmark: //')"
  fi
done <<< "$plan"

# --- the tables -----------------------------------------------------------------------------------
echo
"$bin/paper_benchmark_summary" "$out" --scale "$scale" \
  || fail "the summary could not be written (see the message above)"
echo
echo "Tables: $out/summary.md and summary.json; Fig. 10: $out/fig10_*.svg; records: $out/runs/"
if [ ${#unfinished[@]} -gt 0 ]; then
  echo "run_paper_benchmark.sh: ${#unfinished[@]} of $total runs did not finish:" >&2
  printf '  %s\n' "${unfinished[@]}" >&2
  exit 1
fi
