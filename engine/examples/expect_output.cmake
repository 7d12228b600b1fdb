# cmake -DPROGRAM=exe -DEXPECTED=file -P expect_output.cmake
# Runs PROGRAM and fails unless it exits with 0 and its standard output is exactly EXPECTED's text.
execute_process(COMMAND ${PROGRAM} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors
                TIMEOUT 60)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} exited with ${status}\n${errors}")
endif()
file(READ ${EXPECTED} expected)
if(NOT output STREQUAL expected)
    message(FATAL_ERROR "${PROGRAM} printed\n${output}\nexpected (${EXPECTED})\n${expected}")
endif()
message(STATUS "${PROGRAM}: output as expected")
