# Runs a program and checks what it did, for tests of the command-line tools:
#   cmake -DPROGRAM=exe -DARGS="a|b|c" -DEXPECT_EXIT=N [-DEXPECT_OUTPUT=regex]
#         [-DJSON_FILE=file -DJSON_CHECKS="path.to.field:OP:value|..."] -P run_program.cmake
# OP is EQUAL, LESS, GREATER (numbers) or STREQUAL (strings). A crash (a signal) never matches
# an expected exit code, so "it failed as it should" cannot pass by crashing.
string(REPLACE "|" ";" arguments "${ARGS}")
if(JSON_FILE)
  file(REMOVE "${JSON_FILE}")
endif()
execute_process(COMMAND "${PROGRAM}" ${arguments}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
message("${out}${err}")
if(NOT "${exit_code}" STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "exit code '${exit_code}', expected ${EXPECT_EXIT}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "the output does not match '${EXPECT_OUTPUT}'")
endif()

if(JSON_FILE)
  file(READ "${JSON_FILE}" json)
  string(REPLACE "|" ";" checks "${JSON_CHECKS}")
  foreach(check IN LISTS checks)
    string(REPLACE ":" ";" parts "${check}")
    list(GET parts 0 path)
    list(GET parts 1 op)
    list(GET parts 2 expected)
    string(REPLACE "." ";" keys "${path}")
    string(JSON actual ERROR_VARIABLE json_error GET "${json}" ${keys})
    if(json_error)
      message(FATAL_ERROR "${JSON_FILE}: no field ${path} (${json_error})")
    endif()
    if(NOT "${actual}" ${op} "${expected}")
      message(FATAL_ERROR "${JSON_FILE}: ${path} is ${actual}, expected ${op} ${expected}")
    endif()
    message("ok: ${path} = ${actual} (${op} ${expected})")
  endforeach()
endif()
