# The LinuxCNC HAL components (docs/hal.md): on when linuxcnc-uspace-dev's
# headers are there; the rest of nck builds without them.
set(nck_hal_default OFF)
if(EXISTS /usr/include/linuxcnc/hal.h)
  set(nck_hal_default ON)
endif()
option(NCK_HAL "Build the LinuxCNC HAL components nck.so and nck-hal (needs linuxcnc-uspace-dev)" ${nck_hal_default})
if(NOT NCK_HAL)
  message(STATUS "NCK_HAL off: /usr/include/linuxcnc/hal.h not found (install linuxcnc-uspace-dev)")
  return()
endif()
# nck-hal serves the API (--serve) with the server's layers: the
# kernel-only configuration (NCK_APPS off) has no HAL components.
if(NOT NCK_APPS)
  return()
endif()
find_package(CLI11 REQUIRED)
find_library(NCK_LINUXCNC_HAL_LIB linuxcnchal PATHS /usr/lib REQUIRED)
set(NCK_HAL_INCLUDE /usr/include/linuxcnc)

# What nck.cycle does, without HAL: the module links it, the unit test runs it.
add_library(nck_hal_cycle STATIC ${PROJECT_SOURCE_DIR}/apps/hal/cycle.cpp)
target_include_directories(nck_hal_cycle PUBLIC ${PROJECT_SOURCE_DIR}/apps)
target_link_libraries(nck_hal_cycle PUBLIC nck_kernel nck_config)

# nck.so, loaded into rtapi_app by `loadrt nck`: flags as LinuxCNC's
# Makefile.modinc gives a uspace module.
add_library(nck_hal_rt MODULE ${PROJECT_SOURCE_DIR}/apps/hal/nck_rt.cpp)
set_target_properties(nck_hal_rt PROPERTIES OUTPUT_NAME nck PREFIX "" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/hal)
target_compile_definitions(nck_hal_rt PRIVATE RTAPI __MODULE__ USPACE SIM _GNU_SOURCE realtime)
target_include_directories(nck_hal_rt SYSTEM PRIVATE ${NCK_HAL_INCLUDE})
target_link_libraries(nck_hal_rt PRIVATE nck_hal_cycle)

# nck_cia402_sim.so (loadrt nck_cia402_sim count=N): simulated CiA 402
# drives for HAL files without EtherCAT hardware (examples/hal/mill-cia402.hal).
add_library(nck_cia402_sim MODULE ${PROJECT_SOURCE_DIR}/apps/hal/cia402_sim_rt.cpp)
set_target_properties(nck_cia402_sim PROPERTIES PREFIX "" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/hal)
target_compile_definitions(nck_cia402_sim PRIVATE RTAPI __MODULE__ USPACE SIM _GNU_SOURCE realtime)
target_include_directories(nck_cia402_sim SYSTEM PRIVATE ${NCK_HAL_INCLUDE})
target_link_libraries(nck_cia402_sim PRIVATE nck_drives fmt::fmt)

# nck-hal, the userspace component: decoder and preparation, and with
# --serve the API and HMI (apps/hal/hal_api.cpp).
add_executable(nck-hal ${PROJECT_SOURCE_DIR}/apps/hal/nck_hal_main.cpp ${PROJECT_SOURCE_DIR}/apps/hal/hal_api.cpp)
set_target_properties(nck-hal PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/hal)
target_compile_definitions(nck-hal PRIVATE ULAPI _GNU_SOURCE)
target_include_directories(nck-hal SYSTEM PRIVATE ${NCK_HAL_INCLUDE})
target_include_directories(nck-hal PRIVATE ${PROJECT_SOURCE_DIR}/apps)
target_link_libraries(nck-hal PRIVATE nck_serve nck_run nck_prep CLI11::CLI11 ${NCK_LINUXCNC_HAL_LIB})

# The nck-hal Debian package (component "hal", cmake/package.cmake): the
# module where rtapi_app loads modules from, nck-hal beside halrun.
install(TARGETS nck_hal_rt nck_cia402_sim LIBRARY DESTINATION lib/linuxcnc/modules COMPONENT hal)
install(TARGETS nck-hal RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT hal)
# nck.so is built against this LinuxCNC's HAL ABI (hal.h's structures,
# rtapi_app's loader): the package depends on exactly this version.
execute_process(COMMAND dpkg-query -W "-f=\${Version}" linuxcnc-uspace-dev
                OUTPUT_VARIABLE NCK_LINUXCNC_VERSION RESULT_VARIABLE dpkg_rc ERROR_QUIET)
if(dpkg_rc EQUAL 0 AND NCK_LINUXCNC_VERSION)
  set(CPACK_DEBIAN_HAL_PACKAGE_DEPENDS "linuxcnc-uspace (= ${NCK_LINUXCNC_VERSION})")
else()
  message(STATUS "linuxcnc-uspace-dev is not a Debian package here: the nck-hal package names no LinuxCNC version")
endif()
