# ctest package.embedding (cmake -P): installs this build's libraries and
# headers (component dev) into a fresh prefix, builds tests/embedding
# against it with find_package(nck), runs it on examples/mill/contour.nc
# and compares its end time with `nck run`'s end event. Then checks that
# nck.pc gives the same libraries to pkg-config, and that the kernel-only
# configuration (NCK_APPS=OFF) configures without Boost, CLI11, pybind11,
# GoogleTest or node_modules, also as add_subdirectory(nck). First: a
# prefix nobody may write (under /proc, even for root) fails with CMake's
# message naming it, and nothing is installed.
#   -DBUILD_DIR= -DSOURCE_DIR= -DNCK= -DWORK= -DCXX_FLAGS= -DBUILD_TYPE=
include(${CMAKE_CURRENT_LIST_DIR}/run_checked.cmake)

file(REMOVE_RECURSE ${WORK})
set(denied /proc/nck-install-test)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${denied} --component dev
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "cannot create directory: ${denied}" OR EXISTS ${denied})
  message(FATAL_ERROR "an install into a prefix without write access: exit ${rc}\n${out}\n${err}")
endif()
message(STATUS "a prefix without write access: exit ${rc}, \"${err}\"")

set(prefix ${WORK}/prefix)
run_checked(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component dev)
foreach(f lib/cmake/nck/nckConfig.cmake lib/cmake/nck/nckConfigVersion.cmake lib/pkgconfig/nck.pc
          include/nck/kernel/kernel.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "the install has no ${f}")
  endif()
endforeach()

run_checked(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/embedding -B ${WORK}/consumer -G Ninja
            -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}")
run_checked(${CMAKE_COMMAND} --build ${WORK}/consumer)
run_checked(${WORK}/consumer/embedding ${SOURCE_DIR}/examples/mill ${SOURCE_DIR}/examples/mill/contour.nc)
string(REGEX MATCH "end ([0-9.]+) s" _ "${last_output}")
set(embedded_s ${CMAKE_MATCH_1})
run_checked(${NCK} run ${SOURCE_DIR}/examples/mill ${SOURCE_DIR}/examples/mill/contour.nc --events ${WORK}/e.jsonl)
file(STRINGS ${WORK}/e.jsonl end_line REGEX "\"ev\":\"end\"")
string(REGEX MATCH "\"t\":([0-9.]+)" _ "${end_line}")
if(NOT embedded_s OR NOT embedded_s EQUAL CMAKE_MATCH_1)
  message(FATAL_ERROR "embedded end ${embedded_s} s, nck run's end event at ${CMAKE_MATCH_1} s")
endif()
message(STATUS "find_package(nck): contour.nc ends at ${embedded_s} s, as nck run's end event")

find_program(PKG_CONFIG pkg-config)
if(PKG_CONFIG)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  run_checked(${PKG_CONFIG} --libs --cflags nck)
  string(REGEX MATCH "-I([^ \n]+)" _ "${last_output}")
  if(NOT EXISTS ${CMAKE_MATCH_1}/nck/kernel/kernel.hpp OR NOT last_output MATCHES "-lnck_sim .*-lnck_kernel .*-lnck_core")
    message(FATAL_ERROR "pkg-config nck: ${last_output}")
  endif()
endif()

# The kernel-only configuration: every other package made unfindable.
run_checked(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/kernel-only -G Ninja -DNCK_APPS=OFF
            -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
            -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
            -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON -DCMAKE_DISABLE_FIND_PACKAGE_Python3=ON)
run_checked(${CMAKE_COMMAND} --build ${WORK}/kernel-only --target help)
if(NOT last_output MATCHES "nck_kernel" OR last_output MATCHES "nck_serve|nck_run")
  message(FATAL_ERROR "the kernel-only configuration's targets:\n${last_output}")
endif()
message(STATUS "NCK_APPS=OFF configures nck::kernel..nck::sim alone")

# add_subdirectory(nck) for a kernel-only user (tests/embedding/subdirectory).
run_checked(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/embedding/subdirectory -B ${WORK}/subdirectory -G Ninja
            -DNCK_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_DISABLE_FIND_PACKAGE_Boost=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON
            -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON)
file(READ ${WORK}/subdirectory/build.ninja rules)
if(NOT rules MATCHES "build embedding:" OR rules MATCHES "nck_serve")
  message(FATAL_ERROR "add_subdirectory(nck) with NCK_APPS OFF: no embedding target, or the server came along")
endif()
message(STATUS "add_subdirectory(nck) with NCK_APPS OFF configures")
