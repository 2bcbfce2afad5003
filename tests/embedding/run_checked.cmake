# run_checked(COMMAND...): runs a command and stops the script with its
# output when it fails; its stdout and stderr end up in last_output.
# (The command is a CMake list: an argument cannot hold a ";".)
function(run_checked)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()
