# `cmake --install`: the libraries an engine links, their headers, the shader files, the tables
# and a package config (find_package(rsaa) gives rsaa::core and rsaa::pass).
option(RSAA_INSTALL "Generate the install rules and the rsaa package config" ${RSAA_IS_TOP_LEVEL})
if(NOT RSAA_INSTALL)
  return()
endif()
include(CMakePackageConfigHelpers)

set(RSAA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rsaa)
set(RSAA_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/rsaa)

# core/ headers, by family (include/rsaa/core/{rsaa,reference,util}/).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rsaa/core
        FILES_MATCHING PATTERN "*.h")

set(RSAA_INSTALLED_TARGETS rsaa_core)
if(RSAA_WITH_RUNTIME)
  list(APPEND RSAA_INSTALLED_TARGETS rsaa_pass)
  install(FILES ${RSAA_PUBLIC_RUNTIME_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rsaa/runtime)
endif()
install(TARGETS ${RSAA_INSTALLED_TARGETS} EXPORT rsaaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT rsaaTargets NAMESPACE rsaa:: DESTINATION ${RSAA_INSTALL_CMAKEDIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${RSAA_INSTALL_DATADIR}/shaders)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tables/ DESTINATION ${RSAA_INSTALL_DATADIR}/tables)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${RSAA_INSTALL_DATADIR})
if(TARGET rsaa)
  install(TARGETS rsaa RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(TARGETS rsaa_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/rsaa)
endif()

set(RSAA_PACKAGE_WITH_PASS ${RSAA_WITH_RUNTIME})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rsaaConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rsaaConfig.cmake
                              INSTALL_DESTINATION ${RSAA_INSTALL_CMAKEDIR}
                              PATH_VARS RSAA_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rsaaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rsaaConfig.cmake ${PROJECT_BINARY_DIR}/rsaaConfigVersion.cmake
        DESTINATION ${RSAA_INSTALL_CMAKEDIR})
