# Build speed (tests/README.md, "How long the loop takes"): how often the compiler reads and compiles
# the same headers, never what the programs do. Included at the end of the top CMakeLists.txt, once
# every target exists; a target this build does not make is passed over.
#
# Only the test programs and polarcade-bounds: there GoogleTest, Eigen and the standard library are
# most of each file's compile. An engine source at -O3 (or -O1 with the sanitizers) spends its time
# optimising its own code; a precompiled header saved it nothing (world.cpp 9.9 s either way) and a
# unity batch would make a one-line change recompile its neighbours. CLI11 is in none of them: only
# engine/cli/cli.cpp includes it.

# Unity build: a test program's (and polarcade-bounds') sources compiled in batches of
# POLAR_UNITY_BATCH, one compiler run a batch, so the headers are parsed and their templates
# instantiated once a batch (four game tests: 36 s one by one, 20 s as one batch). Names at file scope, an anonymous namespace's included, must
# then differ between the files of a program; the files below still share one with another file
# and are compiled on their own until renamed (a stale name here matches nothing and costs nothing).
option(POLAR_UNITY "Compile the test programs' sources in batches (unity build)" ON)
set(POLAR_UNITY_BATCH 8 CACHE STRING "Sources in one unity batch of a test program")
set(polar_unity_alone
    # engine tests: kDt, Pair, circle, Body, Objects, parse, expectError, expectIdentical, kEverything, ...
    tests/engine/world/world_test.cpp tests/engine/broad_phase/detector_test.cpp
    tests/engine/objects/effects_test.cpp tests/engine/narrow_phase/exact_contact_test.cpp
    tests/engine/narrow_phase/edge_contact_test.cpp tests/engine/files/bounds_file_test.cpp
    tests/engine/world/ccd_test.cpp tests/engine/narrow_phase/hard_cases_test.cpp
    tests/engine/narrow_phase/accuracy_test.cpp tests/engine/broad_phase/sort_and_sweep_test.cpp
    tests/engine/world/world_snapshot_test.cpp tests/engine/world/allocation_test.cpp
    tests/engine/world/parallel_step_test.cpp tests/engine/files/bounds_round_trip_test.cpp
    # render tests: replaces the global operator new (GCC warns -Wmismatched-new-delete once it
    # sees the replacement inlined into a neighbour's batch)
    tests/engine/render/draw_list_test.cpp
    # game tests: circleBounds, writeSolidPng, writeText
    tests/game/files/mod_overlay_test.cpp tests/game/bad_input_test.cpp tests/game/replay/replay_test.cpp
    # tool tests: Outcome, collide
    tests/tools/collide_accuracy_test.cpp tests/tools/bounds_png_test.cpp tests/tools/bounds_view_test.cpp
    tests/tools/collide_test.cpp
    # polarcade-bounds: fail, fixed
    tools/bounds/gen.cpp tools/bounds/edit.cpp)
list(TRANSFORM polar_unity_alone PREPEND ${PROJECT_SOURCE_DIR}/)

# Precompiled headers: the same programs precompile the standard library, Eigen and (the tests)
# GoogleTest once each; a file that sits out of the batches then starts from them. With ccache,
# tools/setup sets the sloppiness its manual asks for (pch_defines,time_macros).
option(POLAR_PCH "Precompile the standard library, Eigen and GoogleTest headers for the test programs and tools" ON)
set(polar_pch_std <algorithm> <array> <cmath> <cstdint> <cstdio> <cstring> <filesystem> <fstream>
    <functional> <map> <memory> <optional> <span> <sstream> <string> <string_view> <utility> <vector>
    <Eigen/Core>)

# polar_build_speed(TARGET UNITY PCH_HEADERS...): unity batches (UNITY ON) and precompiled headers.
function(polar_build_speed target unity)
    if(NOT TARGET ${target})
        return()
    endif()
    if(POLAR_UNITY AND unity)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${POLAR_UNITY_BATCH})
        set_source_files_properties(${polar_unity_alone} TARGET_DIRECTORY ${target}
            PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
    if(POLAR_PCH)
        target_precompile_headers(${target} PRIVATE ${polar_pch_std} ${ARGN})
    endif()
    # A test program's paths header (PolarBuildPaths.cmake) comes with its precompiled headers.
    polar_include_build_paths(${target} ${POLAR_PCH})
    # With the headers read in another order, GCC 12 inlines std::string's operator+ in a few tests
    # and then warns -Wstringop-overflow or -Warray-bounds inside libstdc++ (false positives of that
    # release, GCC bug 105651, the kind of -Wrestrict in the top CMakeLists.txt); they say nothing
    # about this code.
    if((POLAR_PCH OR POLAR_UNITY) AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-array-bounds)
    endif()
endfunction()

foreach(test polar-engine-tests polar-render-tests polar-game-tests polar-tools-tests)
    polar_build_speed(${test} ON <gtest/gtest.h>)
endforeach()
polar_build_speed(polarcade-bounds ON)
polar_build_speed(polar-server-tests OFF <gtest/gtest.h>)
# polarcade-bench has neither: nine of its files share names (Options, run, registrar).
