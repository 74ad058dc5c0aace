// The environment's brightest texels (its sun), kept apart from the rest by
// pbr::splitBrightTexels so that the convolutions sum them exactly instead of sampling them: a
// sample either hits a small sun thousands of times brighter than the sky or misses it, and
// either way the texel is wrong. What is summed here is what the sampled rest lacks.
const int MAX_BRIGHT_TEXELS = 64;  // pbr::kMaxBrightTexels
uniform vec4 brightDirection[MAX_BRIGHT_TEXELS];  // xyz: the texel centre's unit direction; w: its solid angle
uniform vec3 brightRadiance[MAX_BRIGHT_TEXELS];   // the radiance above the threshold, in its colour
uniform int brightCount;
