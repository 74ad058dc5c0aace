// The output transform of the direct-light samples: Reinhard, then gamma 1/2.2.
// Mirrored on the CPU by pbr::cpu::reinhardGamma.

vec3 reinhard(vec3 color)
{
    return color / (color + vec3(1.0));
}

vec3 gammaCorrect(vec3 color)
{
    return pow(color, vec3(1.0 / 2.2));
}
