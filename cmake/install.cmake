# `cmake --install build --prefix P`: the libraries, their public headers and a CMake
# package, so that another project does find_package(spt) and links spt::core,
# spt::render (and spt::offscreen for contexts without a window). docs/library.md.
include(CMakePackageConfigHelpers)

set(spt_targets spt_core)
set(spt_with_render FALSE)
if(TARGET spt_render)
  list(APPEND spt_targets spt_render spt_offscreen)
  set(spt_with_render TRUE)
endif()
install(TARGETS ${spt_targets} EXPORT sptTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY core/include/spt ${PROJECT_BINARY_DIR}/core/include/spt
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
if(TARGET spt_render)
  install(DIRECTORY render/include/spt DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
endif()
install(PROGRAMS $<TARGET_FILE:spt> DESTINATION ${CMAKE_INSTALL_BINDIR})

set(spt_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/spt)
install(EXPORT sptTargets NAMESPACE spt:: DESTINATION ${spt_cmake_dir})
configure_package_config_file(cmake/sptConfig.cmake.in ${PROJECT_BINARY_DIR}/sptConfig.cmake
  INSTALL_DESTINATION ${spt_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sptConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sptConfig.cmake ${PROJECT_BINARY_DIR}/sptConfigVersion.cmake
  DESTINATION ${spt_cmake_dir})
