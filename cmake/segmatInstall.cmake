include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS segmat EXPORT segmatTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/segmat DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT segmatTargets NAMESPACE segmat:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/segmat)
configure_package_config_file(cmake/segmatConfig.cmake.in
  ${CMAKE_BINARY_DIR}/segmatConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/segmat)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/segmatConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/segmatConfig.cmake ${CMAKE_BINARY_DIR}/segmatConfigVersion.cmake
  cmake/segmatDependencies.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/segmat)
