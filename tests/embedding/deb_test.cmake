# ctest package.deb (cmake -P): builds this build's Debian packages nck,
# python3-nck and (with HAL=ON) nck-hal with CPack, unpacks them with
# dpkg-deb -x into a scratch folder (never dpkg -i: the test does not touch
# the host) and runs what they carry: the binary on the packaged mill
# example, the Python module from the packaged dist-packages folder, and
# (HAL_SESSION=ON) the packaged nck.so and nck-hal in a HAL session of
# their own (scripts/hal-demo.sh) on a short program of the packaged mill.
#   -DBUILD_DIR= -DSOURCE_DIR= -DWORK= -DPYTHON= -DHAL=ON|OFF -DHAL_SESSION=ON|OFF
include(${CMAKE_CURRENT_LIST_DIR}/run_checked.cmake)

file(REMOVE_RECURSE ${WORK})
# Under the sanitizers ctest preloads their runtime for the Python step;
# cpack, strip, dpkg-shlibdeps and xz must not run with it (the test timed
# out at 600 s under ASan): it is put back for the Python step only.
set(preload "$ENV{LD_PRELOAD}")
unset(ENV{LD_PRELOAD})
# The build's CPack configuration without nck-dev (it would only add the
# static libraries package.embedding installs already).
set(components runtime python)
if(HAL)
  list(APPEND components hal)
endif()
file(WRITE ${WORK}/cpack.cmake "include(${BUILD_DIR}/CPackConfig.cmake)\nset(CPACK_COMPONENTS_ALL ${components})\n")
run_checked(cpack -G DEB -B ${WORK}/debs --config ${WORK}/cpack.cmake)
file(GLOB debs ${WORK}/debs/*.deb)
list(LENGTH debs n)
list(LENGTH components expected)
if(NOT n EQUAL expected)
  message(FATAL_ERROR "expected a package for each of ${components}, got: ${debs}")
endif()
set(root ${WORK}/root)
foreach(deb IN LISTS debs)
  run_checked(dpkg-deb -x ${deb} ${root})
  run_checked(dpkg-deb -f ${deb} Package Version Depends)
  message(STATUS "${last_output}")
endforeach()

if(HAL)
  include(${CMAKE_CURRENT_LIST_DIR}/deb_hal_check.cmake)
endif()

set(examples ${root}/usr/share/nck/examples)
run_checked(${root}/usr/bin/nck run ${examples}/mill ${examples}/mill/contour.nc --final ${WORK}/final.json)
if(NOT last_output MATCHES "program_end after 0:00:29.620 simulated")
  message(FATAL_ERROR "the packaged nck: ${last_output}")
endif()

set(ENV{PYTHONPATH} ${root}/usr/lib/python3/dist-packages)
set(ENV{LD_PRELOAD} "${preload}")
check_module_runs(${PYTHON} ${examples} "${root}/usr/lib/python3/dist-packages/nck/__init__.py"
                  "the packaged Python module")
message(STATUS "nck and python3-nck unpacked and run: ${last_output}")
