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

# check_module_runs(PYTHON EXAMPLES WHERE_REGEX WHAT): that PYTHON imports
# nck from a path matching WHERE_REGEX and runs EXAMPLES/mill/contour.nc to
# its 29.62 s, as `nck run` does. (No ";" in the code: run_checked's
# arguments are a CMake list.)
function(check_module_runs python examples where what)
  run_checked(${python} -c "import nck
print(nck.__version__, nck.__file__)
print(nck.Machine('${examples}/mill').run('${examples}/mill/contour.nc').time_s)")
  if(NOT last_output MATCHES "${where}" OR NOT last_output MATCHES "29.62")
    message(FATAL_ERROR "${what}: ${last_output}")
  endif()
  set(last_output "${last_output}" PARENT_SCOPE)
endfunction()
