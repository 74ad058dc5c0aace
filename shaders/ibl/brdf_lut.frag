#version 330 core
// The BRDF lookup table. For NdotV along x and roughness along y (texel centres):
// R, G = scale and bias to F0 of the split-sum GGX specular integral (Karis, "Real Shading in
// Unreal Engine 4"), by GGX importance sampling; B (when `sheen` is on) = the directional albedo
// of Charlie sheen (Estevez and Kulla's distribution with alpha = roughness^2, Ashikhmin's
// visibility), the term of the cookbook's "precompute BRDF LUT" recipe, by Charlie importance
// sampling divided by its density (the cookbook's estimator leaves the density out); A (with B) =
// the same albedo with the sheen specification's own visibility (V_Sheen, Charlie's), what the
// albedo scaling of a sheen layer reads (sample 10; Ashikhmin's albedo is up to 0.3 too high for
// smooth sheen and 0.2 too low for rough, so scaling by B would gain or lose light). Checked
// against a numerical quadrature on the CPU (pbr::cpu::splitSumQuadrature, sheenQuadrature,
// sheenAlbedoQuadrature).
out vec4 FragColor;
in vec2 TexCoords;

uniform int sampleCount;
uniform bool sheen;
// The masking-shadowing term of R and G: false, the texts' Schlick-GGX with k = roughness^2 / 2
// (LearnOpenGL's and the cookbook's table, 04-06); true, the glTF BRDF's own height-correlated
// Smith visibility V_GGX (brdf.glsl), so that the table holds the directional albedo of the lobe
// that 07, 08 and 10 light with.
uniform bool heightCorrelated;

#include "importance_sampling.glsl"
#include "sheen.glsl"

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
        float VdotH = max(dot(V, H), 0.0);
        float NdotL = 2.0 * VdotH * H.z - V.z;  // L = 2 (V.H) H - V, a unit vector: only its z
        float NdotH = max(H.z, 0.0);
        if (NdotL > 0.0)
        {
            // D divides out of D G / (4 NdotL NdotV) NdotL over the density of L,
            // D NdotH / (4 VdotH): G VdotH / (NdotH NdotV), or with the visibility
            // Vis = G / (4 NdotL NdotV), 4 Vis NdotL VdotH / NdotH
            float G_Vis = heightCorrelated
                              ? 4.0 * V_GGX(NdotL, NdotV, roughness * roughness) * NdotL * VdotH / NdotH
                              : geometrySmithIbl(NdotV, NdotL, roughness) * VdotH / (NdotH * NdotV);
            float c = 1.0 - VdotH;
            float Fc = c * c * c * c * c;  // (1 - VdotH)^5
            A += (1.0 - Fc) * G_Vis;
            B += Fc * G_Vis;
        }
    }
    return vec2(A, B) / float(count);
}

// Ashikhmin's visibility for cloth-like sheen.
float V_Ashikhmin(float NdotL, float NdotV)
{
    return clamp(1.0 / (4.0 * (NdotL + NdotV - NdotL * NdotV)), 0.0, 1.0);
}

// A half vector around +Z from the "Charlie" sheen distribution (Estevez and Kulla) of alpha =
// roughness^2, D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi): its density is D(H) NdotH.
vec3 importanceSampleCharlie(vec2 Xi, float roughness)
{
    float alpha = roughness * roughness;
    float phi = 2.0 * PI * Xi.x;
    float sinTheta = pow(Xi.y, alpha / (2.0 * alpha + 1.0));
    float cosTheta = sqrt(1.0 - sinTheta * sinTheta);
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// The sheen's directional albedo, the integral of D V NdotL over light directions, with
// Ashikhmin's visibility (x) and with Charlie's (y). A sample's light direction has density
// D NdotH / (4 VdotH); D divides out of the estimate, leaving V NdotL 4 VdotH / NdotH.
vec2 integrateSheen(float NdotV, float roughness)
{
    vec3 V = vec3(sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    float alpha = max(roughness * roughness, MIN_SHEEN_ALPHA);
    vec2 sum = vec2(0.0);
    uint count = uint(sampleCount);
    for (uint i = 0u; i < count; ++i)
    {
        vec3 H = importanceSampleCharlie(hammersley(i, count), roughness);
        vec3 L = 2.0 * dot(V, H) * H - V;
        float NdotL = L.z;
        float NdotH = H.z;
        float VdotH = dot(V, H);
        if (NdotL > 0.0 && NdotH > 0.0)
            sum += vec2(V_Ashikhmin(NdotL, NdotV), V_Sheen(NdotL, NdotV, alpha)) * NdotL * 4.0 *
                   VdotH / NdotH;
    }
    return sum / float(count);
}

void main()
{
    float NdotV = TexCoords.x;
    float roughness = TexCoords.y;
    FragColor = vec4(integrateBRDF(NdotV, roughness),
                     sheen ? integrateSheen(NdotV, roughness) : vec2(0.0, 1.0));
}
