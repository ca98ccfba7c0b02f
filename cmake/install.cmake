# cmake --install: the libraries of every layer but the command line, their headers under
# include/apollonius3d/<layer>/, the apollonius3d binary, and the CMake package apollonius3d.
include(CMakePackageConfigHelpers)
set(apollonius3d_installed_layers predicates diagram octree topology reference measure mesh io certify)
set(apollonius3d_header_folders
  predicates predicates
  src/diagram diagram
  src/octree octree
  src/topology topology
  src/reference reference
  src/measure measure
  src/mesh mesh
  src/io io
  certify certify)

foreach(layer ${apollonius3d_installed_layers})
  list(APPEND apollonius3d_installed_targets apollonius3d_${layer})
endforeach()
install(TARGETS ${apollonius3d_installed_targets} apollonius3d_library EXPORT apollonius3dTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS apollonius3d RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
while(apollonius3d_header_folders)
  list(POP_FRONT apollonius3d_header_folders source destination)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${source}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/apollonius3d/${destination}
          FILES_MATCHING PATTERN "*.h")
endwhile()

set(apollonius3d_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/apollonius3d)
install(EXPORT apollonius3dTargets NAMESPACE apollonius3d:: DESTINATION ${apollonius3d_config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/apollonius3dConfig.cmake.in
  ${PROJECT_BINARY_DIR}/apollonius3dConfig.cmake INSTALL_DESTINATION ${apollonius3d_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/apollonius3dConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/apollonius3dConfig.cmake ${PROJECT_BINARY_DIR}/apollonius3dConfigVersion.cmake
        DESTINATION ${apollonius3d_config_dir})
