/* stb's image reader and writer, compiled once where the system has the headers alone (the
 * header-only packages of Homebrew and vcpkg, or Debian's without pkg-config: the windowed-only
 * check). Debian's libstb-dev ships them compiled, and this file is not used there. The font
 * rasterizer and rectangle packer are Debian's Dear ImGui's (libimgui.a calls libstb's). */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_PERLIN_IMPLEMENTATION
#define STB_RECT_PACK_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#include <stb_perlin.h>
#include <stb_rect_pack.h>
#include <stb_truetype.h>
