# The browser build: configured by ./build.sh web through emcmake (Debian's emscripten 3.1.6) into
# build/web. The same samples/NN/main.cpp, common/ and shaders/ as the native build, for WebGL 2;
# what the web needs differently lives in common/ behind PBR_WEBGL (common/gl/gl.h). Each sample is
# a page (.html with its shaders and assets inside) beside the program every page runs and the
# bundles it loads (build/web/assets, each a <script src>), so it opens from file:// as
# well as from any static server (samples/CMakeLists.txt).
#
# Its assets are the ones a native build baked (PBR_BAKED_RESOURCES, build/release/resources):
# the recipes are native programs.
if(NOT PBR_BAKED_RESOURCES OR NOT EXISTS "${PBR_BAKED_RESOURCES}/materials/rusted_iron/albedo.png")
    message(FATAL_ERROR "the web build embeds the assets a native build baked: configure with "
                        "-DPBR_BAKED_RESOURCES=<native build>/resources (./build.sh web does: "
                        "it builds the Release preset first)")
endif()
set(PBR_BUILD_TESTS OFF)
set(PBR_BUILD_TOOLS OFF)

# emscripten runs node scripts when it links (acorn, from Debian's node-acorn in
# /usr/share/nodejs); a node that does not search there by itself is told to.
if(EXISTS /usr/share/nodejs AND NOT DEFINED ENV{NODE_PATH})
    set(CMAKE_C_LINKER_LAUNCHER "${CMAKE_COMMAND}" -E env NODE_PATH=/usr/share/nodejs)
    set(CMAKE_CXX_LINKER_LAUNCHER "${CMAKE_COMMAND}" -E env NODE_PATH=/usr/share/nodejs)
endif()

# JavaScript-side C++ exceptions (emscripten's default is to abort on a throw): the error policy
# (one line, an exit code, every destructor run) holds in the page too.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# GLM and stb are header libraries from Debian's packages. em++ must never see /usr/include (its
# own libc++ and libc are elsewhere), so each is reached through a folder holding only it.
set(PBR_WEB_INCLUDE_DIR "${CMAKE_BINARY_DIR}/include")
file(MAKE_DIRECTORY "${PBR_WEB_INCLUDE_DIR}")
foreach(library glm stb)
    find_path(PBR_${library}_ROOT ${library} PATHS /usr/include /usr/local/include
              NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
    if(NOT PBR_${library}_ROOT)
        message(FATAL_ERROR "the web build needs ${library}'s headers (Debian: lib${library}-dev)")
    endif()
    file(CREATE_LINK "${PBR_${library}_ROOT}/${library}" "${PBR_WEB_INCLUDE_DIR}/${library}" SYMBOLIC)
endforeach()
add_library(glm_headers INTERFACE)
target_include_directories(glm_headers SYSTEM INTERFACE "${PBR_WEB_INCLUDE_DIR}")
add_library(glm::glm ALIAS glm_headers)
# Debian's libstb is a native library: the implementation is compiled here (cmake/stb.c).
add_library(pbr_stb STATIC cmake/stb.c)
target_include_directories(pbr_stb SYSTEM PUBLIC "${PBR_WEB_INCLUDE_DIR}/stb")

include(cmake/Glad.cmake)
