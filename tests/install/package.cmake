# The Debian package, built from this build tree and looked into as a player's apt would see it.
#   cmake -DPOLAR_BUILD=<build dir> -DVERSION=<project version> -DDPKG_DEB=<dpkg-deb>
#         -DDESKTOP_VALIDATE=<desktop-file-validate> -DAPPSTREAMCLI=<appstreamcli> -P package.cmake
# Runs CPack (the DEB generator, shlibdeps on) into a scratch folder, then checks the file name,
# the control fields (Depends computed from the shared libraries: SDL2, SDL2_image and libpng among them),
# the contents listed by dpkg-deb -c (binaries, assets, desktop file, icon, metainfo, man pages; no
# engine headers or static libraries), and validates the desktop entry and the AppStream metainfo
# with Debian's validators.
foreach(arg POLAR_BUILD VERSION DPKG_DEB DESKTOP_VALIDATE APPSTREAMCLI)
    if(NOT DEFINED ${arg} OR NOT ${arg} OR ${arg} MATCHES "NOTFOUND$")
        message(FATAL_ERROR "package.cmake needs -D${arg}=… (tools/setup installs dpkg-dev, "
                            "desktop-file-utils and appstream)")
    endif()
endforeach()

# A folder of this run's own (CPack stages into it too): two runs of the suite from one build tree
# at once must not remove each other's package half-way through.
string(RANDOM LENGTH 10 run_id)
set(work "${POLAR_BUILD}/package-test-${run_id}")
file(REMOVE_RECURSE "${work}")

function(fail text)
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "${text}")
endfunction()

function(run what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors
                    TIMEOUT 300)
    if(NOT status EQUAL 0)
        fail("${what} failed (${status}):\n${ARGN}\n${output}${errors}")
    endif()
    set(run_output "${output}" PARENT_SCOPE)
endfunction()

run("cpack" ${CMAKE_CPACK_COMMAND} --config "${POLAR_BUILD}/CPackConfig.cmake" -B "${work}")
run("dpkg --print-architecture" dpkg --print-architecture)
string(STRIP "${run_output}" arch)
set(deb "${work}/polarcade_${VERSION}_${arch}.deb")
if(NOT EXISTS "${deb}")
    file(GLOB made "${work}/*.deb")
    fail("expected ${deb}; CPack made: ${made}")
endif()

foreach(field Package Version Architecture Section Depends)
    run("dpkg-deb -f ${field}" ${DPKG_DEB} -f "${deb}" ${field})
    string(STRIP "${run_output}" ${field})
endforeach()
if(NOT Package STREQUAL "polarcade" OR NOT Version STREQUAL "${VERSION}" OR NOT Architecture STREQUAL "${arch}"
   OR NOT Section STREQUAL "games")
    fail("control fields: Package ${Package}, Version ${Version}, Architecture ${Architecture}, Section ${Section}")
endif()
foreach(library libsdl2-2.0-0 libsdl2-image-2.0-0 libpng16-16 libstdc\\+\\+6 libc6)
    if(NOT Depends MATCHES "(^|, )${library} ")
        fail("Depends has no ${library} with a version: ${Depends}")
    endif()
endforeach()

run("dpkg-deb -c" ${DPKG_DEB} -c "${deb}")
set(contents "${run_output}")
foreach(file usr/bin/polarcade usr/bin/polarcade-replay usr/bin/polarcade-bounds usr/bin/polarcade-collide
             usr/bin/polarcade-server usr/bin/polarcade-boards usr/share/man/man1/polarcade-server.1.gz
             usr/share/man/man1/polarcade-boards.1.gz
             usr/share/polarcade/scenes/cave.json usr/share/polarcade/sprites/ship.png
             usr/share/polarcade/sprites/ship.bounds.json usr/share/applications/polarcade.desktop
             usr/share/icons/hicolor/scalable/apps/polarcade.svg
             usr/share/metainfo/io.github.polarcade.Polarcade.metainfo.xml usr/share/man/man6/polarcade.6.gz
             usr/share/man/man1/polarcade-replay.1.gz usr/share/doc/polarcade/README.md
             usr/share/doc/polarcade/changelog.gz)
    string(REPLACE "+" "\\+" pattern "${file}")
    if(NOT contents MATCHES " \\./${pattern}\n")
        fail("the package has no /${file}:\n${contents}")
    endif()
endforeach()
if(contents MATCHES "\\./usr/(include|lib)/")
    fail("the package holds the engine's development files:\n${contents}")
endif()
if(NOT contents MATCHES "-rwxr-xr-x root/root [^\n]* \\./usr/bin/polarcade\n")
    fail("/usr/bin/polarcade is not an executable owned by root:\n${contents}")
endif()

# The desktop entry and the metainfo, as installed, pass Debian's validators.
run("dpkg-deb -x" ${DPKG_DEB} -x "${deb}" "${work}/root")
# The installed guide: the commands and paths of an installed game, and every /usr/share path it
# names is in the package.
file(READ "${work}/root/usr/share/doc/polarcade/README.md" guide)
if(guide MATCHES "build/bin/|assets/docs/example-mod|source-tree")
    fail("the installed guide names source-tree places (build/bin/, assets/docs/example-mod)")
endif()
string(REGEX MATCHALL "/usr/share/[A-Za-z0-9_./-]*[A-Za-z0-9_]" named "${guide}")
list(REMOVE_DUPLICATES named)
if(NOT named)
    fail("the installed guide names no installed place (the example mod's, say)")
endif()
foreach(place IN LISTS named)
    if(NOT EXISTS "${work}/root${place}")
        fail("the installed guide names ${place}, which the package does not hold")
    endif()
endforeach()

run("desktop-file-validate" ${DESKTOP_VALIDATE} "${work}/root/usr/share/applications/polarcade.desktop")
run("appstreamcli validate" ${APPSTREAMCLI} validate --no-net --pedantic
    "${work}/root/usr/share/metainfo/io.github.polarcade.Polarcade.metainfo.xml")

file(REMOVE_RECURSE "${work}")
message(STATUS "${deb} holds the game, its assets and desktop files; Depends: ${Depends}")
