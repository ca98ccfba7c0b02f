# apollonius3d_layer(NAME FOLDER SOURCES...): the static library of one layer, apollonius3d_NAME, whose
# headers are included as "FOLDER/header.h" from the source tree or from include/apollonius3d when installed.
function(apollonius3d_layer name include_root)
  add_library(apollonius3d_${name} STATIC ${ARGN})
  add_library(apollonius3d::${name} ALIAS apollonius3d_${name})
  set_target_properties(apollonius3d_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(apollonius3d_${name} PUBLIC
    $<BUILD_INTERFACE:${include_root}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/apollonius3d>)
  # CGAL's headers dominate compile times; each layer precompiles them once (not exported).
  target_precompile_headers(apollonius3d_${name} PRIVATE ${PROJECT_SOURCE_DIR}/predicates/number_types.h)
  set_property(GLOBAL APPEND PROPERTY APOLLONIUS3D_LAYERS apollonius3d_${name})
endfunction()
