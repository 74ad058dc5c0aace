# Dear ImGui for the live panel (common/app/panel.*): Debian's libimgui-dev, its static library
# (the core, with its fonts) and the OpenGL 3 backend compiled here from the source the package
# ships among its examples, on our own glad loader (the library's copy loads GL through libGL and
# GLX, which an OSMesa or EGL context does not answer). Nothing is vendored or downloaded. Without
# the package (another system) the samples build without a panel, saying so.
find_path(PBR_IMGUI_INCLUDE_DIR imgui.h PATH_SUFFIXES imgui)
find_library(PBR_IMGUI_LIBRARY imgui)
find_file(PBR_IMGUI_OPENGL3_SOURCE imgui_impl_opengl3.cpp
          PATHS /usr/share/doc/libimgui-dev/examples/backends "${PBR_IMGUI_INCLUDE_DIR}/backends"
          NO_DEFAULT_PATH)
if(PBR_IMGUI_INCLUDE_DIR AND PBR_IMGUI_LIBRARY AND PBR_IMGUI_OPENGL3_SOURCE)
    add_library(pbr_imgui STATIC "${CMAKE_CURRENT_LIST_DIR}/imgui_opengl3.cpp")
    target_include_directories(pbr_imgui SYSTEM PUBLIC "${PBR_IMGUI_INCLUDE_DIR}"
                                                      "${PBR_IMGUI_INCLUDE_DIR}/backends")
    target_compile_definitions(pbr_imgui PRIVATE
        PBR_IMGUI_OPENGL3_SOURCE="${PBR_IMGUI_OPENGL3_SOURCE}" IMGUI_IMPL_OPENGL_LOADER_CUSTOM)
    # Debian's libimgui.a takes its font rasterizer and rectangle packer from libstb (pbr_stb)
    target_link_libraries(pbr_imgui PUBLIC "${PBR_IMGUI_LIBRARY}" pbr_stb glad)
    set(PBR_HAVE_IMGUI ON)
    message(STATUS "the live panel: Dear ImGui from ${PBR_IMGUI_LIBRARY}")
else()
    set(PBR_HAVE_IMGUI OFF)
    message(STATUS "no Dear ImGui (Debian: libimgui-dev): the samples build without the live panel")
endif()
