# The Debian package, made by CPack's DEB generator (tools/package runs it):
#   polarcade_VERSION_ARCH.deb, installing the component Polarcade (install.cmake) under /usr.
# Its Depends line is computed by dpkg-shlibdeps from the shared libraries the binaries link
# (SDL2, libpng, libstdc++, libc), so apt brings them on a fresh Debian. The engine's static
# libraries and headers are for developers and stay out of it.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME polarcade)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Polarcade")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "2D arcade game: fly a ship through a cave of tumbling rocks")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};Polarcade;/")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)

set(POLARCADE_PACKAGE_MAINTAINER "Polarcade developers <polarcade@example.org>" CACHE STRING
    "The Maintainer field of the Debian package")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${POLARCADE_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The long description, below the summary that CPack puts on the first line; at most 80 columns a
# line, and "." is an empty line.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Polarcade is a 2D arcade game on SDL2. You fly a ship in an irregular
cave while rocks tumble and bounce off each other and the cave wall; shoot them
and they split. Comets pass straight through the rock, and shields and extra
lives drop from broken rocks.
.
The game is deterministic and records every game as a replay; polarcade-replay
verifies replays headless, for game developers and CI. Mods lay new sprites,
collision bounds and scenes over the game's files and reload while it runs.")

# Debian wants a changelog in every package: one entry for this version, dated when configured (or
# at SOURCE_DATE_EPOCH, for a reproducible package), compressed without a time stamp.
string(TIMESTAMP polar_changelog_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
configure_file(${polar_dist}/changelog.in ${polar_dist_out}/changelog @ONLY)
add_custom_command(OUTPUT ${polar_dist_out}/changelog.gz
    COMMAND gzip -9nc ${polar_dist_out}/changelog > ${polar_dist_out}/changelog.gz
    DEPENDS ${polar_dist_out}/changelog VERBATIM)
add_custom_target(polarcade-changelog ALL DEPENDS ${polar_dist_out}/changelog.gz)
install(FILES ${polar_dist_out}/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Polarcade)

include(CPack)
