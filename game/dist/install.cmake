# Installing the game: `cmake --install build --prefix P` (component Polarcade) lays out
#   P/bin/polarcade, polarcade-replay, polarcade-bounds, polarcade-collide, polarcade-server,
#         polarcade-boards
#   P/share/polarcade/                   the assets (scenes/, sprites/): the game finds them from
#                                        its own folder, so P can be moved (game/assets.cpp)
#   P/share/doc/polarcade/               the modding guide (assets/README.md) and its docs/
#   P/share/applications/polarcade.desktop, P/share/icons/hicolor/scalable/apps/polarcade.svg
#   P/share/metainfo/io.github.polarcade.Polarcade.metainfo.xml (AppStream)
#   P/share/man/man6/polarcade.6.gz, P/share/man/man1/<tool>.1.gz
# The engine's libraries and headers are the component Polar_Development (engine/cmake).
# Included from the top CMakeLists.txt once every executable exists; the sources of the desktop
# entry, icon, metainfo and man page are beside this file.
include(GNUInstallDirs)
set(polar_dist ${CMAKE_CURRENT_LIST_DIR})
set(polar_dist_out ${CMAKE_BINARY_DIR}/dist)
set(POLARCADE_INSTALLED_TOOLS polarcade-replay polarcade-bounds polarcade-collide polarcade-server polarcade-boards)

install(TARGETS polarcade ${POLARCADE_INSTALLED_TOOLS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        COMPONENT Polarcade)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/scenes ${PROJECT_SOURCE_DIR}/assets/sprites
        DESTINATION ${POLARCADE_INSTALL_ASSETDIR} COMPONENT Polarcade)
# The guide as installed: the source tree's notes left out (installed_guide.cmake).
add_custom_command(OUTPUT ${polar_dist_out}/README.md
    COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR}/assets/README.md -DOUTPUT=${polar_dist_out}/README.md
            -P ${polar_dist}/installed_guide.cmake
    DEPENDS ${PROJECT_SOURCE_DIR}/assets/README.md ${polar_dist}/installed_guide.cmake VERBATIM)
add_custom_target(polarcade-installed-guide ALL DEPENDS ${polar_dist_out}/README.md)
install(FILES ${polar_dist_out}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Polarcade)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/docs DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Polarcade)

install(FILES ${polar_dist}/polarcade.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications
        COMPONENT Polarcade)
install(FILES ${polar_dist}/polarcade.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps
        COMPONENT Polarcade)
install(FILES ${polar_dist}/io.github.polarcade.Polarcade.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo COMPONENT Polarcade)

# Man pages, compressed as Debian wants them (gzip -n: no name or time stamp, so the bytes are the
# same on every build). The game's is written by hand; each tool's is made by help2man from its
# --help and --version, so it never drifts from the program.
configure_file(${polar_dist}/polarcade.6 ${polar_dist_out}/polarcade.6 @ONLY)
set(polar_man_pages)
add_custom_command(OUTPUT ${polar_dist_out}/polarcade.6.gz
    COMMAND gzip -9nc ${polar_dist_out}/polarcade.6 > ${polar_dist_out}/polarcade.6.gz
    DEPENDS ${polar_dist_out}/polarcade.6 VERBATIM)
list(APPEND polar_man_pages ${polar_dist_out}/polarcade.6.gz)
install(FILES ${polar_dist_out}/polarcade.6.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man6 COMPONENT Polarcade)

find_program(POLAR_HELP2MAN help2man)
if(NOT POLAR_HELP2MAN)
    message(FATAL_ERROR "help2man not found: it makes the tools' man pages (tools/setup installs it)")
endif()
set(polar_tool_summary_polarcade-replay "verify Polarcade replays, for developers and CI")
set(polar_tool_summary_polarcade-bounds "generate, check and draw Polarcade collision bounds")
set(polar_tool_summary_polarcade-collide "run one Polarcade collision pass over a scene")
set(polar_tool_summary_polarcade-server "keep Polarcade world high-score boards of re-played runs")
set(polar_tool_summary_polarcade-boards "submit runs to and read Polarcade world boards")
foreach(tool IN LISTS POLARCADE_INSTALLED_TOOLS)
    add_custom_command(OUTPUT ${polar_dist_out}/${tool}.1.gz
        COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:${tool}> -DOUTPUT=${polar_dist_out}/${tool}.h2m
                -P ${polar_dist}/subcommand_help.cmake
        COMMAND ${POLAR_HELP2MAN} --no-info --section=1 "--name=${polar_tool_summary_${tool}}"
                --opt-include=${polar_dist_out}/${tool}.h2m --output=${polar_dist_out}/${tool}.1 $<TARGET_FILE:${tool}>
        COMMAND gzip -9nf ${polar_dist_out}/${tool}.1
        DEPENDS ${tool} ${polar_dist}/subcommand_help.cmake VERBATIM)
    list(APPEND polar_man_pages ${polar_dist_out}/${tool}.1.gz)
    install(FILES ${polar_dist_out}/${tool}.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT Polarcade)
endforeach()
add_custom_target(polarcade-man-pages ALL DEPENDS ${polar_man_pages})

include(${polar_dist}/package.cmake)
