# Install rules: `cmake --install` gives bin/hikiln, the headers under include/hikiln, and a CMake
# package so another project can `find_package(hikiln)` and link `hikiln::hikiln`.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS hikiln RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS hikiln_library hikiln_drivers hikiln_solvers hikiln_kernels
        EXPORT hikilnTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY kernels solvers drivers DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hikiln
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT hikilnTargets NAMESPACE hikiln:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hikiln)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hikilnConfig.cmake.in
  ${PROJECT_BINARY_DIR}/hikilnConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hikiln)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hikilnConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hikilnConfig.cmake ${PROJECT_BINARY_DIR}/hikilnConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hikiln)
