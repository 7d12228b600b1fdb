# The installed game, moved: its frame is the build tree's, byte for byte.
#   cmake -DPOLAR_BUILD=<build dir> -DBUILD_GAME=<build tree's polarcade> [-DBUILD_TYPE=<type>]
#         -P relocate.cmake
# Installs only the game's component (the executables and assets) into a fresh prefix, renames
# the prefix, then runs the moved polarcade --headless --ticks 600 --screenshot 600:FILE from an
# unrelated working folder, with POLARCADE_ASSETS unset, and compares the PNG file with the one
# the build tree's polarcade writes (the same encoder, so equal bytes are equal pixels and equal
# metadata). Then removes the moved tree's assets and expects one message naming the place
# tried, exit 2, and POLARCADE_ASSETS pointing at the assets to work again.
foreach(arg POLAR_BUILD BUILD_GAME)
    if(NOT DEFINED ${arg})
        message(FATAL_ERROR "relocate.cmake needs -D${arg}=…")
    endif()
endforeach()

if(DEFINED ENV{TMPDIR} AND IS_DIRECTORY "$ENV{TMPDIR}")
    set(temp "$ENV{TMPDIR}")
else()
    set(temp /tmp)
endif()
string(RANDOM LENGTH 10 suffix)
set(work "${temp}/polar-relocate-${suffix}")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}/cwd" "${work}/home")

function(fail text)
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "${text}")
endfunction()

# Runs a command in ${work}/cwd with a scratch HOME and no POLARCADE_* variables; sets `status`,
# `output` and `errors` in the caller.
function(run_game)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=POLARCADE_ASSETS --unset=POLARCADE_DATA
                            HOME=${work}/home XDG_DATA_HOME=${work}/home ${ARGN}
                    WORKING_DIRECTORY "${work}/cwd" RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                    TIMEOUT 300)
    set(status "${code}" PARENT_SCOPE)
    set(output "${out}" PARENT_SCOPE)
    set(errors "${err}" PARENT_SCOPE)
endfunction()

set(config_args)
if(BUILD_TYPE)
    set(config_args --config ${BUILD_TYPE})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --install "${POLAR_BUILD}" --prefix "${work}/installed"
                        --component Polarcade ${config_args}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT code EQUAL 0)
    fail("cmake --install --component Polarcade failed (${code}):\n${out}")
endif()
foreach(file bin/polarcade bin/polarcade-replay share/polarcade/scenes/cave.json share/polarcade/sprites/ship.png
             share/applications/polarcade.desktop share/icons/hicolor/scalable/apps/polarcade.svg
             share/metainfo/io.github.polarcade.Polarcade.metainfo.xml share/man/man6/polarcade.6.gz
             share/man/man1/polarcade-replay.1.gz share/doc/polarcade/README.md)
    if(NOT EXISTS "${work}/installed/${file}")
        fail("the install has no ${file}")
    endif()
endforeach()
file(GLOB_RECURSE engine_files "${work}/installed/include/*" "${work}/installed/lib/*")
if(engine_files)
    fail("the game's component installed the engine's development files: ${engine_files}")
endif()

file(RENAME "${work}/installed" "${work}/moved")
set(game "${work}/moved/bin/polarcade")

run_game("${BUILD_GAME}" --headless --ticks 600 --screenshot 600:${work}/build-tree.png)
if(NOT status EQUAL 0)
    fail("the build tree's polarcade failed (${status}):\n${output}${errors}")
endif()
run_game("${game}" --headless --ticks 600 --screenshot 600:moved.png)
if(NOT status EQUAL 0)
    fail("the moved polarcade failed (${status}):\n${output}${errors}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${work}/build-tree.png" "${work}/cwd/moved.png"
                RESULT_VARIABLE differs)
if(NOT differs EQUAL 0)
    fail("the moved install's frame after tick 600 differs from the build tree's")
endif()

# Its --help sends the modder to the guide installed beside it, not to the source tree's.
run_game("${game}" --help)
if(NOT output MATCHES "Modding: see ${work}/moved/share/doc/polarcade/README\\.md\\.")
    fail("the moved polarcade --help does not name its installed guide:\n${output}")
endif()
if(NOT EXISTS "${work}/moved/share/doc/polarcade/README.md")
    fail("the installed guide is not at ${work}/moved/share/doc/polarcade/README.md")
endif()

# Without its assets: one line naming the place tried, exit 2.
file(RENAME "${work}/moved/share/polarcade" "${work}/assets-elsewhere")
run_game("${game}" --headless --ticks 1)
set(expected "polarcade: no asset folder found; tried ${work}/moved/share/polarcade (no such folder); expected a folder with scenes/ and sprites/ (POLARCADE_ASSETS=DIR chooses one)\n")
if(NOT status EQUAL 2 OR NOT errors STREQUAL expected)
    fail("without its assets the moved polarcade gave exit ${status} and\n${errors}\nexpected exit 2 and\n${expected}")
endif()
# POLARCADE_ASSETS names them wherever they are.
run_game(${CMAKE_COMMAND} -E env POLARCADE_ASSETS=${work}/assets-elsewhere "${game}" --headless --ticks 600
         --screenshot 600:override.png)
if(NOT status EQUAL 0)
    fail("POLARCADE_ASSETS=${work}/assets-elsewhere polarcade failed (${status}):\n${errors}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${work}/build-tree.png" "${work}/cwd/override.png"
                RESULT_VARIABLE differs)
if(NOT differs EQUAL 0)
    fail("the frame with POLARCADE_ASSETS differs from the build tree's")
endif()

file(REMOVE_RECURSE "${work}")
message(STATUS "the moved install draws the build tree's frame; without assets it says where it looked")
