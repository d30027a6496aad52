# Remeshes one mesh with remesh_conformal and with remesh_conformal_mpi under mpirun (a rank for
# the tool and the others for the patch jobs), and checks that the two output files are the same
# byte for byte and that the workers ran jobs.
#
#   cmake -DTOOL=remesh_conformal -DMPI_TOOL=remesh_conformal_mpi -DMPIEXEC=mpiexec -DRANKS=3
#         -DMESH=file -DOUT_DIR=directory [-DOPTIONS=a;b] -P remesh_conformal_mpi.cmake
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
execute_process(COMMAND "${TOOL}" "${MESH}" "${OUT_DIR}/single.off" --quiet ${OPTIONS}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "remesh_conformal exited with ${exit_code}: ${output}")
endif()
# As root, OpenMPI runs only when told to; on a small machine it needs --oversubscribe for more
# ranks than cores.
execute_process(COMMAND "${MPIEXEC}" --allow-run-as-root --oversubscribe -np ${RANKS} "${MPI_TOOL}" "${MESH}"
                        "${OUT_DIR}/mpi.off" --quiet ${OPTIONS}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "mpirun -np ${RANKS} remesh_conformal_mpi exited with ${exit_code}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT_DIR}/single.off" "${OUT_DIR}/mpi.off" RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "${OUT_DIR}/mpi.off differs from ${OUT_DIR}/single.off")
endif()
if(RANKS GREATER 1 AND NOT output MATCHES "worker ranks ran [1-9][0-9]* patch jobs")
  message(FATAL_ERROR "no patch job ran on a worker rank")
endif()
file(SIZE "${OUT_DIR}/mpi.off" size)
message("same output (${size} bytes) with ${RANKS} ranks")
