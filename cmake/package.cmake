# `cpack -G DEB` in a build folder (or `make deb`): spt_VERSION_amd64.deb with the library, its
# headers and CMake package, the programs with their desktop entries and icons, the Python module,
# and the docs.
# Library dependencies of the programs come from dpkg-shlibdeps; what only dlopen or the CMake
# package needs is named here (docs/library.md, "Installing the Debian package").
install(FILES README.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
if(TARGET spt-editor)
  install(FILES resources/desktop/spt-editor.desktop resources/desktop/spt-viewer.desktop
    DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES resources/desktop/spt-editor.svg resources/desktop/spt-viewer.svg
    DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
endif()

set(CPACK_PACKAGE_NAME spt)
set(CPACK_PACKAGE_VENDOR "The spt authors")
set(CPACK_PACKAGE_CONTACT "The spt authors <spt@example.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "collision detection with sampling trees: library, editor, viewer")
set(CPACK_PACKAGE_DESCRIPTION "Sphere-based collision detection (Yea & Han's sampling trees): \
the spt command (convert, info, query, simulate, render), the four-view editor spt-editor, \
the scene viewer spt-viewer, the C++ library spt::core with its CMake package, and the Python \
module spt (import spt).")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # spt_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.invalid/spt")
# find_package(spt) asks for these (cmake/sptConfig.cmake.in): the static library links them (and
# Bullet, by library name: effect dynamics).
set(spt_deb_depends "libeigen3-dev (>= 3.4), libassimp-dev, zlib1g-dev, libtbb-dev, libbullet-dev")
if(TARGET spt_render)
  # `spt render` opens libOSMesa or libEGL by soname when it first draws (render/src/gl_library.hpp),
  # which dpkg-shlibdeps cannot see.
  string(APPEND spt_deb_depends ", libpng-dev, libosmesa6 | libegl-mesa0")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libosmesa6, libegl1, libegl-mesa0")
endif()
if(TARGET spt_python)
  string(APPEND spt_deb_depends ", ${SPT_PYTHON_DEB_DEPENDS}") # python/CMakeLists.txt
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${spt_deb_depends}")
include(CPack)
