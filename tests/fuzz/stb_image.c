/* stb's image reader and writer for the fuzz build (CMakeLists.txt says why it is compiled here):
 * what files/image.cpp calls of Debian's libstb, from the same headers. */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
