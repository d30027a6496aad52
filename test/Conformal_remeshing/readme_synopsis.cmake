# Checks that the top-level README.md shows a command-line tool's synopsis as the tool prints it,
# so that the two cannot drift apart.
#
#   cmake -DPROGRAM=path/to/tool -DNAME=tool -DREADME=path/to/README.md -P readme_synopsis.cmake
#
# The synopsis is the usage of `PROGRAM --help`: its line "usage: NAME ..." and the lines right
# after it that continue it (indented, starting with "["). README.md must hold exactly those lines
# as one fenced block opened by ```text, and every option (--word) that --help mentions must be in
# that block. The README is the one place of the synopses; the user manual points to it.
foreach(variable PROGRAM NAME README)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "readme_synopsis.cmake needs -D${variable}=...")
  endif()
endforeach()

execute_process(COMMAND "${PROGRAM}" --help RESULT_VARIABLE code OUTPUT_VARIABLE help ERROR_VARIABLE errors)
if(NOT code STREQUAL "0")
  message(FATAL_ERROR "'${PROGRAM} --help' exited with ${code}:\n${help}${errors}")
endif()
string(REGEX MATCH "^usage: ${NAME} [^\n]*(\n +\\[[^\n]*)*" synopsis "${help}")
if(synopsis STREQUAL "")
  message(FATAL_ERROR "'${PROGRAM} --help' does not start with 'usage: ${NAME} ':\n${help}")
endif()

file(READ "${README}" readme)
string(FIND "${readme}" "```text\n${synopsis}\n```" position)
if(position EQUAL -1)
  string(FIND "${readme}" "```text\nusage: ${NAME} " start)
  if(start EQUAL -1)
    set(found "no ```text block starting with 'usage: ${NAME} '")
  else()
    string(SUBSTRING "${readme}" ${start} -1 rest)
    string(FIND "${rest}" "\n```" end)
    math(EXPR end "${end} + 4")
    string(SUBSTRING "${rest}" 0 ${end} block)
    set(found "this block:\n${block}")
  endif()
  # The details as plain text: an error message would be rewrapped.
  message("README.md should hold the block\n```text\n${synopsis}\n```\nand has ${found}")
  message(FATAL_ERROR "${README} does not show the synopsis of '${NAME} --help' (see above)")
endif()

string(REGEX MATCHALL "--[a-z][-a-z]*" options "${help}")
list(REMOVE_DUPLICATES options)
foreach(option IN LISTS options)
  string(REGEX MATCH "${option}([^-a-z]|$)" listed "${synopsis}")
  if(listed STREQUAL "")
    message(FATAL_ERROR "'${NAME} --help' describes ${option}, which its usage line (and so README.md's synopsis) does not list")
  endif()
endforeach()
list(LENGTH options count)
message("README.md shows the synopsis of ${NAME} --help (${count} options)")
