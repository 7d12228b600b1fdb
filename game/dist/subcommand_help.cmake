# The man page's section for a tool's subcommands: each one's own --help, so the page lists every
# option of the program, not only the top level's (help2man reads only `TOOL --help`). Written as
# a help2man --opt-include file; none for a tool without subcommands.
#   cmake -DTOOL=bin/polarcade-bounds -DOUTPUT=dist/polarcade-bounds.h2m -P subcommand_help.cmake
execute_process(COMMAND ${TOOL} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${TOOL} --help failed (${status})")
endif()
set(include "")
# CLI11 lists them after "Subcommands:", one "  name   summary" line each, up to a blank line.
if(help MATCHES "\nSubcommands:\n(([^\n]+\n)*)")
    string(REGEX MATCHALL "(^|\n)  [a-z][a-z0-9-]*" names "${CMAKE_MATCH_1}")
    set(include "[SUBCOMMANDS]\n")
    foreach(name IN LISTS names)
        string(STRIP "${name}" name)
        execute_process(COMMAND ${TOOL} ${name} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
        if(NOT status EQUAL 0)
            message(FATAL_ERROR "${TOOL} ${name} --help failed (${status})")
        endif()
        # roff: a backslash is \e, a line may not start with . or ', and - is \- in options.
        string(REPLACE "\\" "\\e" text "${text}")
        string(REPLACE "-" "\\-" text "${text}")
        string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
        string(APPEND include ".SS \"${name}\"\n.nf\n${text}.fi\n")
    endforeach()
endif()
if(include)
    file(WRITE "${OUTPUT}" "${include}")
else()
    file(REMOVE "${OUTPUT}")
endif()
