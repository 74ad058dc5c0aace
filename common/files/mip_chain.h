#pragma once
// The mip chain of an 8-bit image, made on the CPU. The texts call glGenerateMipmap after each
// upload; OpenGL leaves that filter to the driver (the specification asks only for a box filter
// or better), so the chain would differ from one GL to the next. Made here, the chain is the same
// on llvmpipe, a GPU, a browser and Windows, and a software GL does not compile its blit shaders
// for each texture format at each start (100-200 ms a format with Mesa 22's llvmpipe).
#include <vector>

#include "files/image.h"

namespace pbr {

// Levels 1 to the last (1x1) of `image`: each side halved and rounded down, never below 1, as
// glTexImage2D's levels must be. Each texel of a level is what linear filtering reads of the
// level above at the texel's centre, as the blit that Mesa's and the browsers' glGenerateMipmap
// make: where both sides are even, the mean of a 2x2 block (so a texel of level n is the mean of
// a 2^n x 2^n block of level 0); from 5 texels to 2, a quarter and three quarters of two. With
// `srgb`, the colour channels (all but the alpha of a 2- or 4-channel image) hold sRGB codes and
// are filtered as the linear light they encode, then encoded again; other channels are filtered
// as they are. Each level is made from the level above before rounding and rounded to the
// nearest code, so rounding does not add up down the chain. Empty for a 1x1 image.
std::vector<Image> mipChain(const Image& image, bool srgb);

}  // namespace pbr
