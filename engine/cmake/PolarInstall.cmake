# The engine as an installable CMake package. `cmake --install build --prefix P` puts under P:
#   include/polar/**                       the public headers (the libraries' folders, for those built)
#   lib/libpolar_*.a                       the libraries (lib/ is GNUInstallDirs' LIBDIR)
#   lib/cmake/Polar/PolarConfig.cmake      the package: find_package(Polar) gives Polar::engine,
#                                          Polar::render, Polar::authoring and, with SDL, Polar::platform
# so another project needs only CMAKE_PREFIX_PATH=P. Included at the end of engine/CMakeLists.txt,
# once every library target exists. Install rules for the game and its assets belong with them in
# game/ (their own COMPONENT); this file holds only the engine's.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(POLAR_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Polar" CACHE STRING
    "Where the Polar package config is installed, relative to the prefix")

# What a program compiling the headers needs: C++20 (std::span and friends in the API), and no
# fused multiply-add in the inline code of the headers, so it rounds as the libraries do on every
# compiler (the engine's determinism rule).
target_compile_features(polar_engine PUBLIC cxx_std_20)
target_compile_options(polar_engine INTERFACE
    $<INSTALL_INTERFACE:$<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang,AppleClang>:-ffp-contract=off>>)

# Each library that exists, by its exported name (Polar::<name>). A library whose link interface
# names SDL goes into an export set of its own, which the package loads only when SDL is found, so
# a program that links Polar::engine never needs SDL.
set(polar_core_targets)
set(polar_sdl_targets)
foreach(library engine authoring render platform)
    if(NOT TARGET polar_${library})
        continue()
    endif()
    set_target_properties(polar_${library} PROPERTIES EXPORT_NAME ${library})
    get_target_property(links polar_${library} LINK_LIBRARIES)
    get_target_property(interface_links polar_${library} INTERFACE_LINK_LIBRARIES)
    set(needs_sdl OFF)
    foreach(link IN LISTS links interface_links)
        if(TARGET "${link}")
            get_target_property(aliased "${link}" ALIASED_TARGET)
            if(aliased)
                set(link ${aliased})
            endif()
        endif()
        if(link MATCHES "SDL2" OR link IN_LIST polar_sdl_targets)
            set(needs_sdl ON)
        endif()
    endforeach()
    if(needs_sdl)
        list(APPEND polar_sdl_targets polar_${library})
    else()
        list(APPEND polar_core_targets polar_${library})
    endif()
endforeach()

# Headers: the engine's own, and each library's folder when that library is built.
set(polar_header_excludes)
foreach(folder render platform authoring)
    if(NOT TARGET polar_${folder})
        list(APPEND polar_header_excludes PATTERN ${folder} EXCLUDE)
    endif()
endforeach()
install(DIRECTORY include/polar DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT Polar_Development
        FILES_MATCHING PATTERN "*.h" ${polar_header_excludes})

install(TARGETS ${polar_core_targets} EXPORT PolarTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Polar_Development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Polar_Development)
install(EXPORT PolarTargets NAMESPACE Polar:: DESTINATION ${POLAR_INSTALL_CMAKEDIR}
        COMPONENT Polar_Development)
if(polar_sdl_targets)
    install(TARGETS ${polar_sdl_targets} EXPORT PolarPlatformTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Polar_Development
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Polar_Development)
    install(EXPORT PolarPlatformTargets NAMESPACE Polar:: DESTINATION ${POLAR_INSTALL_CMAKEDIR}
            COMPONENT Polar_Development)
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/PolarConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/PolarConfig.cmake INSTALL_DESTINATION ${POLAR_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API, so only the same major.minor satisfies a request.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/PolarConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/PolarConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/PolarConfigVersion.cmake
        DESTINATION ${POLAR_INSTALL_CMAKEDIR} COMPONENT Polar_Development)

# The exported names, for tests that check the installed package (tests/install).
list(TRANSFORM polar_core_targets REPLACE "^polar_" "" OUTPUT_VARIABLE polar_core_names)
list(TRANSFORM polar_sdl_targets REPLACE "^polar_" "" OUTPUT_VARIABLE polar_sdl_names)
set_property(GLOBAL PROPERTY POLAR_INSTALLED_LIBRARIES ${polar_core_names} ${polar_sdl_names})
