#version 330 core
// The prefiltered environment for one roughness (one mip level of the specular cube map): the
// environment averaged over the GGX lobe around the reflection vector, with N = V = R as the
// split-sum approximation assumes. GGX importance sampling with Hammersley points; each sample
// reads the source at the mip level whose texels cover the sample's share of the sphere
// (LOD 0.5 * log2(saSample / saTexel)), which keeps a small bright sun from sparkling.
out vec4 FragColor;
in vec3 WorldPos;

uniform samplerCube environmentMap;
uniform float roughness;
uniform int sampleCount;
uniform float sourceTexelSolidAngle;  // 4 pi / (6 size^2) of the environment's level 0
uniform float footprintLod;  // log2(source size / this level's size): one texel of this level

#include "importance_sampling.glsl"

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
    FragColor = vec4(prefilteredColor / totalWeight, 1.0);
}
