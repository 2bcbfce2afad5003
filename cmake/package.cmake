# The CMake package (find_package(nck)) and pkg-config file of the layers
# this configuration built (docs/embedding.md): static libraries exported
# as nck::<layer>, the public headers under include/nck/, nckConfig.cmake,
# nckConfigVersion.cmake and nck.pc. The libraries and headers form the
# "dev" component; the command line, examples and docs "runtime".
include(CMakePackageConfigHelpers)

get_property(nck_layers GLOBAL PROPERTY NCK_LAYERS)
set(nck_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/nck)
install(TARGETS ${nck_layers} EXPORT nckTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/nck DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev)
install(EXPORT nckTargets NAMESPACE nck:: DESTINATION ${nck_cmake_dir} COMPONENT dev)

# What a consumer must find before the targets resolve: the layers' own
# dependencies (Boost only with the server, header-only).
set(NCK_PACKAGE_DEPS "find_dependency(fmt)\nfind_dependency(nlohmann_json)")
if(NCK_APPS)
  string(APPEND NCK_PACKAGE_DEPS "\nfind_dependency(Threads)\nfind_dependency(Boost 1.74)")
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/nckConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/nckConfig.cmake INSTALL_DESTINATION ${nck_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/nckConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/nckConfig.cmake ${PROJECT_BINARY_DIR}/nckConfigVersion.cmake
        DESTINATION ${nck_cmake_dir} COMPONENT dev)

# pkg-config: every layer built, the highest first (a static link resolves
# left to right).
set(NCK_PC_LIBS "")
foreach(layer IN LISTS nck_layers)
  string(PREPEND NCK_PC_LIBS "-l${layer} ")
endforeach()
if(NCK_APPS)
  string(APPEND NCK_PC_LIBS "-pthread")  # the run service's and the report's threads
endif()
# Relocatable: the prefix is found from where nck.pc lies (an install
# with --prefix or DESTDIR, a .deb unpacked elsewhere).
file(RELATIVE_PATH NCK_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(${PROJECT_SOURCE_DIR}/cmake/nck.pc.in ${PROJECT_BINARY_DIR}/nck.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/nck.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dev)

# Debian packages (cpack -G DEB in the build folder; docs/embedding.md):
# nck (component runtime: the command line, examples under
# /usr/share/nck/examples, docs), nck-dev (dev), python3-nck (python) and,
# with NCK_HAL, nck-hal (hal: nck.so and nck-hal for LinuxCNC, depending on
# the one linuxcnc-uspace version they were built against, cmake/hal.cmake).
# Shared-library dependencies come from dpkg-shlibdeps (libfmt9 ...).
set(CPACK_PACKAGE_NAME nck)
set(CPACK_PACKAGE_VENDOR "the nck developers")
set(CPACK_PACKAGE_CONTACT "nck developers <nck@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "open NC kernel: ISG machine lists, DIN 66025 / ISG programs, cycle by cycle")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME nck)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME nck-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "nck (= ${PROJECT_VERSION}), libfmt-dev, nlohmann-json3-dev")
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-nck)
set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "python3 (>= 3.11), python3-numpy")
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_DEBIAN_HAL_PACKAGE_NAME nck-hal)
set(CPACK_DEBIAN_HAL_PACKAGE_RECOMMENDS nck)  # the HAL examples ship in nck (/usr/share/nck/examples/hal)
set(CPACK_DEBIAN_HAL_PACKAGE_SECTION misc)
set(CPACK_COMPONENT_HAL_DESCRIPTION "nck's real-time kernel as LinuxCNC HAL components (loadrt nck, loadusr nck-hal)")
include(CPack)
