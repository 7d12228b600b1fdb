# The installed package, checked as a user would use it:
#   cmake -DPOLAR_BUILD=<build dir> -DCONSUMER=<tests/install/consumer> -DEXPECTED=<output file>
#         -DLIBRARIES=<installed library names, comma-separated> -DGENERATOR=<generator>
#         -DCOMPILER=<c++ compiler> -DBUILD_TYPE=<type> [-DCONSUMER_FLAGS=<flags>]
#         -P install_consumer.cmake
# Installs the build into a fresh prefix under the build dir, copies the consumer project to a
# temporary folder outside the source tree, configures it with only CMAKE_PREFIX_PATH pointing at
# the prefix, builds it, runs it and compares its output with EXPECTED. Then builds a second
# program that includes and links every installed library. Any failure fails the test.
foreach(arg POLAR_BUILD CONSUMER EXPECTED GENERATOR COMPILER)
    if(NOT DEFINED ${arg})
        message(FATAL_ERROR "install_consumer.cmake needs -D${arg}=…")
    endif()
endforeach()

# Ends the test with a message, removing the temporary copy of the consumer first.
function(fail text)
    if(work)
        file(REMOVE_RECURSE "${work}")
    endif()
    if(install_root)
        file(REMOVE_RECURSE "${install_root}")
    endif()
    message(FATAL_ERROR "${text}")
endfunction()

# Runs a command; any failure ends the test with its output.
function(run what)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output
                    TIMEOUT 300)
    if(NOT status EQUAL 0)
        fail("${what} failed (${status}):\n${ARGN}\n${output}")
    endif()
    set(run_output "${output}" PARENT_SCOPE)
endfunction()

# A prefix of this run's own: two runs of the suite from one build tree at once (a loaded CI
# machine, tools/test beside a developer's ctest) must not install into or remove each other's.
string(RANDOM LENGTH 10 run_id)
set(install_root "${POLAR_BUILD}/install-test-${run_id}")
set(prefix "${install_root}/prefix")
file(REMOVE_RECURSE "${install_root}")
set(config_args)
if(BUILD_TYPE)
    set(config_args --config ${BUILD_TYPE})
endif()
run("cmake --install" ${CMAKE_COMMAND} --install "${POLAR_BUILD}" --prefix "${prefix}" ${config_args})
foreach(file include/polar/polar.h include/polar/world.h)
    if(NOT EXISTS "${prefix}/${file}")
        fail("the install has no ${file}")
    endif()
endforeach()
file(GLOB_RECURSE configs "${prefix}/*/PolarConfig.cmake" "${prefix}/*/PolarConfigVersion.cmake")
list(LENGTH configs config_count)
if(NOT config_count EQUAL 2)
    fail("expected PolarConfig.cmake and PolarConfigVersion.cmake under ${prefix}, found: ${configs}")
endif()
file(GLOB_RECURSE private_headers "${prefix}/include/*/detector.h" "${prefix}/include/*/pair_rule.h")
if(private_headers)
    fail("private headers were installed: ${private_headers}")
endif()

# Outside the source tree, so nothing can reach the repository by a relative path.
if(DEFINED ENV{TMPDIR} AND IS_DIRECTORY "$ENV{TMPDIR}")
    set(temp "$ENV{TMPDIR}")
else()
    set(temp /tmp)
endif()
string(RANDOM LENGTH 10 suffix)
set(work "${temp}/polar-consumer-${suffix}")
file(REMOVE_RECURSE "${work}")
file(COPY "${CONSUMER}/" DESTINATION "${work}/source")

set(common -G "${GENERATOR}" -DCMAKE_CXX_COMPILER=${COMPILER})
if(BUILD_TYPE)
    list(APPEND common -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
endif()
if(CONSUMER_FLAGS)
    list(APPEND common "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}")
endif()

# 1. The engine alone, found through CMAKE_PREFIX_PATH and nothing else.
run("configuring the consumer" ${CMAKE_COMMAND} -S "${work}/source" -B "${work}/build" ${common}
    "-DCMAKE_PREFIX_PATH=${prefix}")
file(STRINGS "${work}/build/CMakeCache.txt" polar_dir REGEX "^Polar_DIR:")
string(FIND "${polar_dir}" "${prefix}/" at)
if(NOT at GREATER -1)
    fail("the consumer found Polar outside the fresh prefix ${prefix}: ${polar_dir}")
endif()
run("building the consumer" ${CMAKE_COMMAND} --build "${work}/build" --parallel 2)
run("running the consumer" "${work}/build/consumer")
file(READ "${EXPECTED}" expected)
if(NOT run_output STREQUAL expected)
    fail("the consumer printed\n${run_output}\nexpected (${EXPECTED})\n${expected}")
endif()

# 2. Every installed library as a required component, its headers included and the library linked.
if(LIBRARIES)
    run("configuring the consumer with ${LIBRARIES}" ${CMAKE_COMMAND} -S "${work}/source" -B "${work}/build-all"
        ${common} "-DCMAKE_PREFIX_PATH=${prefix}" "-DPOLAR_LIBRARIES=${LIBRARIES}")
    run("building against ${LIBRARIES}" ${CMAKE_COMMAND} --build "${work}/build-all" --parallel 2)
    run("running consumer-libraries" "${work}/build-all/consumer-libraries")
endif()

file(REMOVE_RECURSE "${work}" "${install_root}")
message(STATUS "the installed package builds and runs a consumer (${LIBRARIES})")
