#version 330 core
// The environment prefiltered by the sheen's lobe, for one sheen roughness (one mip level of the
// sheen cube map): the average of the environment around the normal weighted by
// D_Charlie(H) N.L, with N = V as the split sum assumes (H halfway between N and L). That weight
// depends only on L's angle from N and gathers at the horizon, a ring the smoother the narrower:
// it is summed by a fixed rule, not sampled. Rings at the angles and with the weights the CPU
// computed (pbr::prefilterSheen: Gauss-Legendre nodes in the angle, their weights over the lobe's
// integral), each read at `ringTaps` azimuths, staggered ring to ring, at the mip level whose
// texels cover one tap's share of the ring. The environment's bright texels (its sun) are summed
// exactly, each weighted by D N.L and its solid angle over the lobe's integral.
out vec4 FragColor;
in vec3 WorldPos;

const int MAX_RINGS = 32;  // pbr::kSheenPrefilterRings
uniform samplerCube environmentMap;  // the rest of the environment, less its bright texels
uniform int ringCount;
uniform int ringTaps;
uniform float ringCos[MAX_RINGS];     // cos of the ring's angle from N
uniform float ringWeight[MAX_RINGS];  // its share of the lobe's weight, for all its taps
uniform float ringLod[MAX_RINGS];     // the mip level of one tap's footprint
uniform float alpha;                  // sheenRoughness^2
uniform float lobeNormalization;      // the integral of D N.L (pbr::sheenPrefilterNormalization)

#include "importance_sampling.glsl"
#include "sheen.glsl"
#include "bright_texels.glsl"

void main()
{
    vec3 N = normalize(WorldPos);
    mat3 toWorld = tangentFrame(N);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < ringCount; ++i)
    {
        float cosTheta = ringCos[i];
        float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
        vec3 ring = vec3(0.0);
        for (int k = 0; k < ringTaps; ++k)
        {
            float phi = 2.0 * PI * (float(k) + 0.5 * float(i % 2)) / float(ringTaps);
            vec3 L = toWorld * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
            ring += textureLod(environmentMap, L, ringLod[i]).rgb;
        }
        sum += ring * (ringWeight[i] / float(ringTaps));
    }
    vec3 bright = vec3(0.0);
    for (int i = 0; i < brightCount; ++i)
    {
        vec3 L = brightDirection[i].xyz;
        float NdotL = dot(N, L);
        if (NdotL > 0.0)
        {
            float D = D_Charlie(dot(N, normalize(N + L)), alpha);
            bright += brightRadiance[i] * (brightDirection[i].w * D * NdotL);
        }
    }
    FragColor = vec4(sum + bright / lobeNormalization, 1.0);
}
