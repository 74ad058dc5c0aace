// The exact sRGB transfer functions (IEC 61966-2-1), for outputs that must match an sRGB
// framebuffer or texture to the last bit. Mirrored in tests by the same formulas.

vec3 linearToSrgb(vec3 linear)
{
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
