/* stb's image reader and writer, compiled once where the system has the headers alone (the
 * header-only packages of Homebrew and vcpkg). Debian's libstb-dev ships them compiled, and this
 * file is not used there. */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_PERLIN_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
#include <stb_perlin.h>
