# Runs the paper benchmark's four remeshers on one small mesh as if it were Table 1's shield, then
# its summary, and checks: every run is recorded (status "ok" with an output, a peak memory and
# both Hausdorff distances, or, for Gmsh and MeshLab only, failed because the program is not
# installed: CI need not install them), and the summary's quality table has a row for every
# remesher that ran.
#
#   cmake -DPROGRAM=paper_benchmark -DSUMMARY=paper_benchmark_summary -DMESH=file -DDIR=directory
#         -P paper_benchmark_peers.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}/runs")
set(ran "")
foreach(method IN ITEMS conformal isotropic gmsh meshlab)
  set(json_file "${DIR}/runs/table_shield_${method}.json")
  execute_process(COMMAND "${PROGRAM}" run "${MESH}" "${json_file}" --method ${method} --name shield
                          --target-edge-length 0.2 --time-limit 120
                  RESULT_VARIABLE exit_code OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message("${output}")
  file(READ "${json_file}" json)
  string(JSON status GET "${json}" status)
  if(exit_code EQUAL 0 AND status STREQUAL "ok")
    string(JSON vertices GET "${json}" output vertices)
    string(JSON peak GET "${json}" peak_mb)
    string(JSON to_input GET "${json}" fidelity relative_hausdorff_to_reference)
    string(JSON from_input GET "${json}" fidelity relative_hausdorff_from_reference)
    if(NOT vertices GREATER 100 OR NOT peak GREATER 0 OR NOT to_input GREATER 0 OR NOT from_input GREATER 0
       OR to_input GREATER 0.01 OR from_input GREATER 0.01)
      message(FATAL_ERROR "${json_file}: ${vertices} vertices, peak ${peak} MB, Hausdorff ${to_input} / ${from_input}")
    endif()
    list(APPEND ran ${method})
  else()
    string(JSON error ERROR_VARIABLE ignored GET "${json}" error)
    if(NOT exit_code EQUAL 1 OR NOT error MATCHES "not installed" OR method MATCHES "conformal|isotropic")
      message(FATAL_ERROR "${method}: exit code ${exit_code}, status ${status}: ${error}")
    endif()
  endif()
  message("ok: ${method}: ${status}")
endforeach()
execute_process(COMMAND "${SUMMARY}" "${DIR}" --scale small RESULT_VARIABLE exit_code OUTPUT_QUIET ERROR_VARIABLE error)
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "paper_benchmark_summary exited with ${exit_code}: ${error}")
endif()
file(READ "${DIR}/summary.md" summary)
foreach(method IN LISTS ran)
  if(NOT summary MATCHES "\\|  \\| ${method} \\| [0-9.]+ \\| [0-9.k]+ \\| [0-9.]+ \\|")
    message(FATAL_ERROR "${DIR}/summary.md: no quality row for ${method}")
  endif()
endforeach()
if(NOT EXISTS "${DIR}/fig10_shield.svg")
  message(FATAL_ERROR "no ${DIR}/fig10_shield.svg")
endif()
message("summary rows: ${ran}")
