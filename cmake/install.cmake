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
# The config file looks for the private dependencies only when a consumer links them:
# the export names them as $<LINK_ONLY:...> for a static libdisktune, not at all for a
# shared one.
get_target_property(_disktune_type disktune TYPE)
if(_disktune_type STREQUAL "STATIC_LIBRARY")
  set(DISKTUNE_STATIC TRUE)
else()
  set(DISKTUNE_STATIC FALSE)
endif()
configure_package_config_file(cmake/disktuneConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/disktune)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/disktuneConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/disktuneConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/disktune)
