# The web build's dependencies and flags (included by the top CMakeLists.txt under emscripten).
#
# Eigen, nlohmann_json, CLI11 and stb are header-only, so the host's Debian packages serve: each
# is reached through a folder of its own (a link in the build tree), never /usr/include itself,
# whose glibc headers would shadow emscripten's. No SDL, and no threads: without SharedArrayBuffer
# a page needs no special headers, and every part runs on one thread (WorldDef::workers 1).
set(POLAR_WEB_INCLUDE ${CMAKE_BINARY_DIR}/host-include)
file(MAKE_DIRECTORY ${POLAR_WEB_INCLUDE})
foreach(dir nlohmann CLI stb)
    if(NOT EXISTS /usr/include/${dir})
        message(FATAL_ERROR "/usr/include/${dir} is missing: tools/web installs what the web build needs")
    endif()
    file(CREATE_LINK /usr/include/${dir} ${POLAR_WEB_INCLUDE}/${dir} SYMBOLIC)
endforeach()
add_library(Eigen3::Eigen INTERFACE IMPORTED)
set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES /usr/include/eigen3)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${POLAR_WEB_INCLUDE})
add_library(CLI11::CLI11 INTERFACE IMPORTED)
set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${POLAR_WEB_INCLUDE})
add_library(Threads::Threads INTERFACE IMPORTED)

# C++ exceptions (CLI11 reports bad arguments with them) as WebAssembly exceptions: no cost until
# one is thrown. Both compiling and linking need the flag.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions -sALLOW_MEMORY_GROWTH=1)

# WebAssembly SIMD128 (fixed-width 128-bit vectors; in Chrome 91, Firefox 89, Safari 16.4 and
# node 16.4 on): the renderer's span kernel uses it (engine/src/render/sprite_span_wasm.cpp). A
# module with SIMD instructions does not load where they are missing; OFF builds one without.
option(POLAR_WEB_SIMD "Draw sprites with WebAssembly SIMD128 in the web build" ON)
