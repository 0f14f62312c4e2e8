# Installing Soak like a Debian program (README.md, "Install"):
#   PREFIX/bin/soak                      the command-line tool
#   PREFIX/lib/soak/libsoak_*.so         its I/O modules (soak/plugin.h)
#   PREFIX/share/soak/                   the data folder (soak/data_dir.h):
#       materials.json, export.schema.json, measured/, scenes/default_wet_dry.json,
#       povray/soak.inc, povray/soak_materials.inc, povray/soak_mesh.inc, soak_blender.zip
#   PREFIX/share/man/man1/soak.1.gz      the manual page, made by `soak --man`
# The executable finds lib/soak and share/soak relative to its own folder, so
# an installed tree works wherever it is moved. These folder names are also
# written in c_core/core/src/plugin.c and data_dir.c: change them together.
# `cpack -G DEB` (or `make package` in the build folder) makes the .deb.

install(TARGETS soak_cli RUNTIME DESTINATION bin)
foreach(module soak_plugin_image soak_plugin_mesh soak_plugin_vdb)
  if(TARGET ${module})
    install(TARGETS ${module} LIBRARY DESTINATION lib/soak)
  endif()
endforeach()

set(SOAK_SHARE share/soak)
install(FILES c_core/data/materials.json c_core/data/export.schema.json DESTINATION ${SOAK_SHARE})
install(DIRECTORY c_core/data/measured DESTINATION ${SOAK_SHARE})
install(FILES scenes/default_wet_dry.json scenes/README.md DESTINATION ${SOAK_SHARE}/scenes)
install(FILES povray/soak.inc povray/soak_materials.inc povray/soak_mesh.inc DESTINATION ${SOAK_SHARE}/povray)
install(FILES README.md DESTINATION share/doc/soak)

# The manual page: `soak --man` prints --help's texts with every command's
# option table, so it cannot fall behind the tool.
set(SOAK_MAN ${CMAKE_BINARY_DIR}/man/soak.1)
find_program(SOAK_GZIP gzip)
if(SOAK_GZIP)
  set(SOAK_MAN_FILE ${SOAK_MAN}.gz)
  set(SOAK_MAN_GZIP_STEP COMMAND ${SOAK_GZIP} -9nf ${SOAK_MAN})
else()
  set(SOAK_MAN_FILE ${SOAK_MAN})
  set(SOAK_MAN_GZIP_STEP "")
endif()
add_custom_command(OUTPUT ${SOAK_MAN_FILE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
  COMMAND ${CMAKE_COMMAND} -DSOAK=$<TARGET_FILE:soak_cli> -DOUT=${SOAK_MAN} -P ${CMAKE_CURRENT_LIST_DIR}/soak_man.cmake
  ${SOAK_MAN_GZIP_STEP}
  DEPENDS soak_cli ${CMAKE_CURRENT_LIST_DIR}/soak_man.cmake
  COMMENT "Writing the manual page (soak --man)")
add_custom_target(soak_man ALL DEPENDS ${SOAK_MAN_FILE})
install(FILES ${SOAK_MAN_FILE} DESTINATION share/man/man1)

# The Blender add-on zip (blender_addon/build_zip.py; the Makefile's `make
# addon` writes the same file), when a Python 3 is at hand.
find_program(SOAK_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(SOAK_PYTHON3 python3)
if(SOAK_PYTHON3)
  file(GLOB_RECURSE SOAK_ADDON_SOURCES CONFIGURE_DEPENDS blender_addon/soak/*.py blender_addon/soak/*.json
       blender_addon/soak/*.toml)
  file(GLOB SOAK_ADDON_OSL CONFIGURE_DEPENDS osl/*.osl)
  set(SOAK_ADDON_ZIP ${CMAKE_BINARY_DIR}/soak_blender.zip)
  add_custom_command(OUTPUT ${SOAK_ADDON_ZIP}
    COMMAND ${SOAK_PYTHON3} ${PROJECT_SOURCE_DIR}/blender_addon/build_zip.py ${SOAK_ADDON_ZIP}
    DEPENDS ${PROJECT_SOURCE_DIR}/blender_addon/build_zip.py ${SOAK_ADDON_SOURCES} ${SOAK_ADDON_OSL}
    COMMENT "Building the Blender add-on zip")
  add_custom_target(soak_addon_zip ALL DEPENDS ${SOAK_ADDON_ZIP})
  install(FILES ${SOAK_ADDON_ZIP} DESTINATION ${SOAK_SHARE})
else()
  message(STATUS "python3 not found: the Blender add-on zip is neither built nor installed")
endif()

# The .deb: Depends from the shared libraries the binary and modules link
# (dpkg-shlibdeps); POV-Ray and Blender run Soak's exports, so suggested.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME soak)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Soak")
set(CPACK_PACKAGE_CONTACT "Soak maintainers <soak-maintainers@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "physically based wet materials: models, reference path tracer and bakers")
# (CPack puts the summary first and indents these lines.)
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Soak computes how porous and non-porous materials look when wet (film
optics, pore water, drying), renders them with a reference path tracer
(soak render), bakes wet maps and parameter volumes (soak bake) and exports
the material data to POV-Ray, Blender and OSL (soak export). The POV-Ray
includes and the Blender add-on zip are in /usr/share/soak.")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "povray, blender")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
include(CPack)
