# Runs remeshing_benchmark with every peer, at the same length and the same size, on one small
# mesh, and checks each model's "peers" record: every peer of both comparisons is there, ran
# ("ok", with vertices) or is not installed (CI does not install Gmsh and MeshLab);
# isotropic_remeshing() always runs.
#
#   cmake -DPROGRAM=remeshing_benchmark -DMESH=file -DJSON_FILE=file -P remeshing_benchmark_peers.cmake
file(REMOVE "${JSON_FILE}")
execute_process(COMMAND "${PROGRAM}" "${JSON_FILE}" --no-generated --relative 0.05 --peers isotropic,gmsh,meshlab
                        --same-size --peer-timeout 60 "${MESH}"
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "remeshing_benchmark exited with ${exit_code}")
endif()
file(READ "${JSON_FILE}" json)
foreach(comparison IN ITEMS same_length same_size)
  foreach(peer IN ITEMS isotropic gmsh meshlab)
    string(JSON status ERROR_VARIABLE error GET "${json}" 0 peers ${comparison} ${peer} status)
    if(error)
      message(FATAL_ERROR "${JSON_FILE}: no status for ${peer} in ${comparison} (${error})")
    endif()
    if(status STREQUAL "ok")
      string(JSON vertices GET "${json}" 0 peers ${comparison} ${peer} measures vertices)
      if(NOT vertices GREATER 0)
        message(FATAL_ERROR "${JSON_FILE}: ${peer} in ${comparison} ran but has ${vertices} vertices")
      endif()
    elseif(NOT status STREQUAL "not installed" OR peer STREQUAL "isotropic")
      string(JSON reason ERROR_VARIABLE ignored GET "${json}" 0 peers ${comparison} ${peer} reason)
      message(FATAL_ERROR "${JSON_FILE}: ${peer} in ${comparison}: ${status} (${reason})")
    endif()
    message("ok: ${comparison} ${peer}: ${status}")
  endforeach()
endforeach()
