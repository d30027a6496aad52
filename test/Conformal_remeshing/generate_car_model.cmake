# Generates a small car assembly twice and checks that the files are the same (the generator is
# deterministic) and that it has Table 1's five parts and more, at least the faces asked for.
#
#   cmake -DPROGRAM=generate_car_model -DOUT_DIR=directory -P generate_car_model.cmake
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
foreach(run IN ITEMS a b)
  execute_process(COMMAND "${PROGRAM}" "${OUT_DIR}/car_${run}.off" --faces 150k --part-scale 0.02
                  RESULT_VARIABLE exit_code OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT exit_code EQUAL 0)
    message(FATAL_ERROR "generate_car_model exited with ${exit_code}: ${output}")
  endif()
endforeach()
message("${output}")
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT_DIR}/car_a.off" "${OUT_DIR}/car_b.off" RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "two runs wrote different files")
endif()
if(NOT output MATCHES "car: [^\n]*: ([0-9]+) parts, [0-9]+ vertices, ([0-9]+) faces")
  message(FATAL_ERROR "no summary line")
endif()
if(CMAKE_MATCH_1 LESS 6 OR CMAKE_MATCH_2 LESS 150000)
  message(FATAL_ERROR "${CMAKE_MATCH_1} parts, ${CMAKE_MATCH_2} faces")
endif()
foreach(part IN ITEMS suspension_arm shield radiator_shell chassis brake_disc)
  if(NOT output MATCHES "  ${part}: ")
    message(FATAL_ERROR "no ${part}")
  endif()
endforeach()
