// The "Charlie" sheen (Conty Estevez and Kulla, "Production Friendly Microfacet Sheen BRDF",
// 2017), as KHR_materials_sheen specifies it: its distribution and its visibility, both with
// alpha = sheenRoughness^2 (as the Khronos viewer squares it). Shared by the BRDF LUT (its A
// channel) and the sheen layer (gltf_extensions.glsl). Mirrored on the CPU by
// common/math/gltf_extensions.cpp. Needs PI (brdf.glsl).

float D_Charlie(float NdotH, float alpha)
{
    float invAlpha = 1.0 / alpha;
    float sin2h = max(1.0 - NdotH * NdotH, 0.0);
    return (2.0 + invAlpha) * pow(sin2h, invAlpha * 0.5) / (2.0 * PI);
}

// The curve fit of the Charlie shadowing's exponent (its lambda), at cosine x.
float charlieL(float x, float alpha)
{
    float t = (1.0 - alpha) * (1.0 - alpha);
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c = mix(0.19823, 0.16801, t);
    float d = mix(-1.97760, -1.27393, t);
    float e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float lambdaSheen(float cosTheta, float alpha)
{
    return abs(cosTheta) < 0.5 ? exp(charlieL(cosTheta, alpha))
                               : exp(2.0 * charlieL(0.5, alpha) - charlieL(1.0 - cosTheta, alpha));
}

// The Charlie visibility, G / (4 NdotL NdotV), at most 1.
float V_Sheen(float NdotL, float NdotV, float alpha)
{
    float g = 1.0 + lambdaSheen(NdotV, alpha) + lambdaSheen(NdotL, alpha);
    return clamp(1.0 / (g * 4.0 * NdotV * NdotL), 0.0, 1.0);
}

// Sheen roughness 0 would make the distribution a spike at the horizon: alpha stays above this.
const float MIN_SHEEN_ALPHA = 1e-6;
