# Writes the installed copy of the modding guide: assets/README.md without what is only true in a
# source tree. The source guide marks it <!--source-tree-->…<!--/source-tree--> (a paragraph, or a
# few words in a line); its commands and paths are already the installed ones.
#   cmake -DSOURCE=assets/README.md -DOUTPUT=dist/README.md -P installed_guide.cmake
file(READ "${SOURCE}" guide)
string(REGEX REPLACE "<!--source-tree-->[^<]*(<[^!][^<]*)*<!--/source-tree-->\n?" "" guide "${guide}")
if(guide MATCHES "build/bin/|assets/docs/example-mod|source-tree")
    message(FATAL_ERROR "${SOURCE}: source-tree paths outside <!--source-tree--> blocks; expected "
                        "every build/bin/ and assets/docs/example-mod inside one")
endif()
file(WRITE "${OUTPUT}" "${guide}")
