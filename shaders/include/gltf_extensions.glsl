// The layers of the advanced glTF materials (sample 10; the cookbook's chapter "Advanced PBR
// extensions"), each as its Khronos extension specifies it, written once. Mirrored on the CPU by
// common/math/gltf_extensions.cpp (same names), which the tests compare against and integrate.
// Needs brdf.glsl first (PI, D_GGX, V_GGX, MIN_GGX_ALPHA).

// ---- KHR_materials_ior ----
// A dielectric's reflectance at normal incidence in air, from its index of refraction:
// ((ior - 1) / (ior + 1))^2, 0.04 at the core material's 1.5.
float iorToF0(float ior)
{
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

// ---- KHR_materials_specular ----
// The dielectric's Fresnel ends: the strength (specular, A of its texture) scales the whole
// reflection and is its grazing value F90; the colour tints the normal-incidence one, which stays
// at or below 1 before the strength: F0 = min(iorToF0(ior) specularColor, 1) specular.
struct DielectricFresnel
{
    vec3 F0;
    float F90;
};

DielectricFresnel dielectricFresnel(float ior, vec3 specularColor, float specular)
{
    DielectricFresnel f;
    f.F0 = min(vec3(iorToF0(ior)) * specularColor, vec3(1.0)) * specular;
    f.F90 = specular;
    return f;
}

// ---- KHR_materials_clearcoat ----
// A clear dielectric coat (F0 from the material's ior, F90 1) over the whole material, with its
// own roughness and normal. Its lobe is a GGX specular (D V, alpha = roughness^2); what it
// reflects is mixed over the layer beneath by the coat's Fresnel at its own normal and the view:
//   coated = mix(base, coat lobe, clearcoat Fc(N_coat . V)),   Fc(x) = F0 + (1 - F0)(1 - x)^5
// so the base loses, at every light, the share the coat reflects.
float clearcoatFresnel(float F0, float NdotV)
{
    return F0 + (1.0 - F0) * pow(1.0 - clamp(NdotV, 0.0, 1.0), 5.0);
}

// The coat's lobe for one light, times NdotL at its normal (radiance 1): D V NdotL.
float clearcoatDirect(vec3 coatN, vec3 V, vec3 L, float roughness)
{
    float NdotL = clamp(dot(coatN, L), 0.0, 1.0);
    float NdotV = clamp(dot(coatN, V), 0.0, 1.0);
    float NdotH = clamp(dot(coatN, normalize(V + L)), 0.0, 1.0);
    float alpha = max(roughness * roughness, MIN_GGX_ALPHA);
    return NdotL * D_GGX(NdotH, alpha) * V_GGX(NdotL, NdotV, alpha);
}

// The layer beneath and the coat, mixed by the coat's strength at this view (clearcoat Fc).
vec3 coatOver(vec3 base, vec3 coat, float coatWeight)
{
    return mix(base, coat, coatWeight);
}

// ---- KHR_materials_sheen ----
// A layer of fibres over the material (Conty Estevez and Kulla, "Production Friendly Microfacet
// Sheen BRDF", 2017): the "Charlie" distribution and its visibility, both with alpha =
// sheenRoughness^2, no Fresnel. The layer beneath is scaled by what the sheen takes from it
// (albedo scaling): 1 - max(sheenColor) E, E the sheen's directional albedo at the view and at
// the light (the smaller of the two), read from a table (the BRDF LUT's sheen channel).
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

// The sheen lobe for one light, times NdotL (radiance 1): sheenColor D V NdotL.
vec3 sheenDirect(vec3 N, vec3 V, vec3 L, vec3 sheenColor, float sheenRoughness)
{
    float NdotL = clamp(dot(N, L), 0.0, 1.0);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    if (NdotL <= 0.0 || NdotV <= 0.0)
        return vec3(0.0);
    float NdotH = clamp(dot(N, normalize(V + L)), 0.0, 1.0);
    float alpha = max(sheenRoughness * sheenRoughness, MIN_SHEEN_ALPHA);
    return sheenColor * (NdotL * D_Charlie(NdotH, alpha) * V_Sheen(NdotL, NdotV, alpha));
}

float max3(vec3 v)
{
    return max(v.x, max(v.y, v.z));
}

// What the layer beneath keeps under the sheen, from the sheen's albedo at the view and the light.
float sheenAlbedoScaling(vec3 sheenColor, float albedoAtV, float albedoAtL)
{
    float strength = max3(sheenColor);
    return min(1.0 - strength * albedoAtV, 1.0 - strength * albedoAtL);
}

// ---- KHR_materials_emissive_strength ----
// The emission, as bright as the strength says (the core material's factor stops at 1), seen
// through the clear coat: emissive strength (1 - clearcoat Fc).
vec3 emission(vec3 emissive, float strength, float coatWeight)
{
    return emissive * strength * (1.0 - coatWeight);
}
