// Dear ImGui's OpenGL 3 backend, compiled from the source Debian's libimgui-dev ships (its path
// is PBR_IMGUI_OPENGL3_SOURCE, see ImGui.cmake) against the project's glad loader, so that it
// draws in every context the samples make: a window, OSMesa and EGL alike.
#include <glad/gl.h>

#include PBR_IMGUI_OPENGL3_SOURCE
