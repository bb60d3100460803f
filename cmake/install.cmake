# SPDX-License-Identifier: GPL-3.0-or-later
# find_package(disktune) for other mesh generators: exported targets, a Config file and
# a version file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS disktune EXPORT disktuneTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/disktune DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT disktuneTargets NAMESPACE disktune::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/disktune)
configure_package_config_file(cmake/disktuneConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/disktune)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/disktuneConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/disktune)
