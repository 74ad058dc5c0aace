#version 330 core
// The prefiltered environment for one roughness (one mip level of the specular cube map): the
// environment averaged over the GGX lobe around the reflection vector, with N = V = R as the
// split-sum approximation assumes. The environment's bright texels (its sun) are summed exactly,
// each weighted by D(H) N.L and its solid angle over the lobe's whole weight; the rest by GGX
// importance sampling with Hammersley points, each sample reading it at the mip level whose
// texels cover the sample's share of the sphere (LOD 0.5 * log2(saSample / saTexel)).
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;  // roughness 0: the environment; else the rest, less its bright texels
uniform float roughness;
uniform int sampleCount;
uniform float sourceTexelSolidAngle;  // 4 pi / (6 size^2) of the environment's level 0
uniform float footprintLod;  // log2(source size / this level's size): one texel of this level
uniform float lobeNormalization;  // the integral of D(H) N.L over N.L > 0 (pbr::prefilterNormalization)

#include "importance_sampling.glsl"
#include "bright_texels.glsl"

void main()
{
    vec3 N = normalize(WorldPos);
    vec3 R = N;
    vec3 V = R;

    // A mirror: every GGX sample is N itself (and D is 0/0 there), so the lobe is one direction.
    // Read it averaged over this texel's footprint rather than at one point of the source.
    if (roughness == 0.0)
    {
        FragColor = vec4(textureLod(environmentMap, N, footprintLod).rgb, 1.0);
        return;
    }

    mat3 toWorld = tangentFrame(N);
    vec3 prefilteredColor = vec3(0.0);
    float totalWeight = 0.0;
    uint count = uint(sampleCount);
    for (uint i = 0u; i < count; ++i)
    {
        vec3 H = toWorld * importanceSampleGGX(hammersley(i, count), roughness);  // unit
        vec3 L = 2.0 * dot(V, H) * H - V;  // the reflection of V about H: unit too
        float NdotL = dot(N, L);
        if (NdotL > 0.0)
        {
            float D = DistributionGGX(N, H, roughness);
            float NdotH = max(dot(N, H), 0.0);
            float HdotV = max(dot(H, V), 0.0);
            float pdf = D * NdotH / (4.0 * HdotV) + 0.0001;  // of L (the text's small offsets)
            float sampleSolidAngle = 1.0 / (float(count) * pdf + 0.0001);
            float lod = max(0.5 * log2(sampleSolidAngle / sourceTexelSolidAngle), 0.0);
            prefilteredColor += textureLod(environmentMap, L, lod).rgb * NdotL;
            totalWeight += NdotL;
        }
    }
    vec3 bright = vec3(0.0);
    for (int i = 0; i < brightCount; ++i)
    {
        vec3 L = brightDirection[i].xyz;
        float NdotL = dot(N, L);
        if (NdotL > 0.0)
        {
            float D = DistributionGGX(N, normalize(V + L), roughness);
            bright += brightRadiance[i] * (brightDirection[i].w * D * NdotL);
        }
    }
    FragColor = vec4(prefilteredColor / totalWeight + bright / lobeNormalization, 1.0);
}
