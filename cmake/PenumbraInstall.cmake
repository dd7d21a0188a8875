# install() with a CMake package config, so that find_package(penumbra) works.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS penumbra penumbra_warnings EXPORT penumbraTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/penumbra DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET penumbra_cli)
  install(TARGETS penumbra_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT penumbraTargets NAMESPACE penumbra::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
configure_package_config_file(cmake/penumbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/penumbraConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/penumbraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/penumbraConfig.cmake
              ${PROJECT_BINARY_DIR}/penumbraConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
