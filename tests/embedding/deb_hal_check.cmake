# Part of deb_test.cmake: the nck-hal package. It must name the one
# linuxcnc-uspace version nck.so was built against, carry nck.so where
# rtapi_app loads modules and nck-hal on the PATH, and (HAL_SESSION) run:
# the packaged pair moves the packaged mill through stepgens to a program
# end in a HAL session of its own.
file(GLOB hal_deb ${WORK}/debs/nck-hal_*.deb)
run_checked(dpkg-deb -f ${hal_deb} Depends)
execute_process(COMMAND dpkg-query -W "-f=\${Version}" linuxcnc-uspace-dev OUTPUT_VARIABLE linuxcnc_version)
string(FIND "${last_output}" "linuxcnc-uspace (= ${linuxcnc_version})" at)
if(at LESS 0)
  message(FATAL_ERROR "nck-hal must depend on linuxcnc-uspace (= ${linuxcnc_version}): ${last_output}")
endif()
foreach(file usr/lib/linuxcnc/modules/nck.so usr/lib/linuxcnc/modules/nck_cia402_sim.so usr/bin/nck-hal)
  if(NOT EXISTS ${root}/${file})
    message(FATAL_ERROR "nck-hal carries no /${file}")
  endif()
endforeach()
if(NOT HAL_SESSION)
  message(STATUS "nck-hal packaged; its HAL session is not run in this build (sanitized: nck.so cannot load into rtapi_app)")
  return()
endif()

# hal-demo.sh runs NCK_BUILD_DIR/hal/{nck.so,nck-hal}: the packaged ones.
file(MAKE_DIRECTORY ${WORK}/hal_bin/hal)
file(COPY ${root}/usr/lib/linuxcnc/modules/nck.so ${root}/usr/bin/nck-hal DESTINATION ${WORK}/hal_bin/hal)
file(WRITE ${WORK}/short.nc "N10 G01 X10 Y5 F3000\nN20 M30\n")
set(ENV{NCK_BUILD_DIR} ${WORK}/hal_bin)
set(ENV{NCK_HAL_TIMEOUT} 60)
execute_process(COMMAND ${SOURCE_DIR}/scripts/hal-demo.sh ${root}/usr/share/nck/examples/hal/mill-stepgen.hal
                        ${WORK}/short.nc ${root}/usr/share/nck/examples/mill
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 77 OR "${err}" MATCHES "unshare.*Operation not permitted")
  message(STATUS "nck-hal packaged; no HAL session here (not root or unshare not permitted)")
elseif(NOT rc EQUAL 0 OR NOT "${out}${err}" MATCHES "channel 1 done")
  message(FATAL_ERROR "the packaged nck-hal in HAL (exit ${rc}):\n${out}\n${err}")
else()
  message(STATUS "the packaged nck.so and nck-hal ran the mill to its program end in HAL")
endif()
