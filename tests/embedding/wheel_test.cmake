# ctest package.wheel (cmake -P): the Python package as pip installs it.
# The sdist builds with no compiler (CC and CXX made to fail); pip installs
# ./python into a fresh venv offline, with its module built by CMake in
# this build folder (NCK_CMAKE_BUILD: already built, so the test costs no
# compile); the venv then imports nck without PYTHONPATH and runs the mill
# example.
#   -DBUILD_DIR= -DSOURCE_DIR= -DWORK= -DPYTHON=
include(${CMAKE_CURRENT_LIST_DIR}/run_checked.cmake)

file(REMOVE_RECURSE ${WORK})
unset(ENV{PYTHONPATH})
set(ENV{PIP_NO_INDEX} 1)  # offline: nothing downloads
set(ENV{CC} /bin/false)
set(ENV{CXX} /bin/false)
run_checked(${PYTHON} -m build --sdist --no-isolation --outdir ${WORK}/dist ${SOURCE_DIR}/python)
file(GLOB sdist ${WORK}/dist/nck-*.tar.gz)
if(NOT sdist)
  message(FATAL_ERROR "no sdist: ${last_output}")
endif()
unset(ENV{CC})
unset(ENV{CXX})

run_checked(${PYTHON} -m venv --system-site-packages ${WORK}/venv)  # numpy from Debian's python3-numpy
set(ENV{NCK_CMAKE_BUILD} ${BUILD_DIR})
run_checked(${WORK}/venv/bin/python -m pip install --no-build-isolation ${SOURCE_DIR}/python)
check_module_runs(${WORK}/venv/bin/python ${SOURCE_DIR}/examples
                  "${WORK}/venv/lib/python3[.0-9]*/site-packages/nck/__init__.py" "nck in the venv")
message(STATUS "sdist ${sdist} without a compiler; pip install ./python: ${last_output}")
