#version 330 core
// The split-sum BRDF lookup table (Karis, "Real Shading in Unreal Engine 4"): for NdotV along x
// and roughness along y, the scale (R) and bias (G) to F0 of the GGX specular integral, by
// importance sampling with Hammersley points. Mirrored on the CPU by pbr::cpu::integrateBrdf.
out vec4 FragColor;
in vec2 TexCoords;

uniform int sampleCount;

const float PI = 3.14159265359;

vec2 hammersley(uint i, uint N)
{
    uint bits = (i << 16u) | (i >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return vec2(float(i) / float(N), float(bits) * 2.3283064365386963e-10);
}

// A half vector around +Z with the GGX distribution of `roughness` (alpha = roughness^2).
vec3 importanceSampleGGX(vec2 Xi, float roughness)
{
    float a = roughness * roughness;
    float phi = 2.0 * PI * Xi.x;
    float cosTheta = sqrt((1.0 - Xi.y) / (1.0 + (a * a - 1.0) * Xi.y));
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Schlick-GGX with k = roughness^2 / 2, the remapping for image-based lighting.
float geometrySmithIbl(float NdotV, float NdotL, float roughness)
{
    float k = roughness * roughness / 2.0;
    return (NdotV / (NdotV * (1.0 - k) + k)) * (NdotL / (NdotL * (1.0 - k) + k));
}

vec2 integrateBRDF(float NdotV, float roughness)
{
    vec3 V = vec3(sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    float A = 0.0;
    float B = 0.0;
    uint count = uint(sampleCount);
    for (uint i = 0u; i < count; ++i)
    {
        vec3 H = importanceSampleGGX(hammersley(i, count), roughness);
        vec3 L = normalize(2.0 * dot(V, H) * H - V);
        float NdotL = max(L.z, 0.0);
        float NdotH = max(H.z, 0.0);
        float VdotH = max(dot(V, H), 0.0);
        if (NdotL > 0.0)
        {
            float G = geometrySmithIbl(NdotV, NdotL, roughness);
            float G_Vis = (G * VdotH) / (NdotH * NdotV);
            float Fc = pow(1.0 - VdotH, 5.0);
            A += (1.0 - Fc) * G_Vis;
            B += Fc * G_Vis;
        }
    }
    return vec2(A, B) / float(count);
}

void main()
{
    FragColor = vec4(integrateBRDF(TexCoords.x, TexCoords.y), 0.0, 1.0);
}
