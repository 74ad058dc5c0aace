// The Cook-Torrance BRDF of LearnOpenGL's PBR chapters, written once for every sample.
// Mirrored on the CPU by common/math/brdf.cpp (same names), which the reference tests compare
// against.

const float PI = 3.14159265359;

// Trowbridge-Reitz GGX normal distribution; roughness is squared first (Disney / Epic).
float DistributionGGX(vec3 N, vec3 H, float roughness)
{
    float a = roughness * roughness;
    float a2 = a * a;
    float NdotH = max(dot(N, H), 0.0);
    float denom = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * denom * denom);
}

// Schlick-GGX for one direction, with k = (roughness + 1)^2 / 8 (the remapping for direct light).
float GeometrySchlickGGX(float NdotV, float roughness)
{
    float r = roughness + 1.0;
    float k = (r * r) / 8.0;
    return NdotV / (NdotV * (1.0 - k) + k);
}

// Smith's method: shadowing towards the light times masking towards the viewer.
float GeometrySmith(vec3 N, vec3 V, vec3 L, float roughness)
{
    float NdotV = max(dot(N, V), 0.0);
    float NdotL = max(dot(N, L), 0.0);
    return GeometrySchlickGGX(NdotV, roughness) * GeometrySchlickGGX(NdotL, roughness);
}

// Fresnel-Schlick: the share of light reflected at angle theta, from F0 at normal incidence.
vec3 fresnelSchlick(float cosTheta, vec3 F0)
{
    return F0 + (1.0 - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// Fresnel-Schlick for the environment: no single half vector, so roughness damps the rise at
// grazing angles (Sebastien Lagarde's approximation, as in LearnOpenGL's IBL chapters).
vec3 fresnelSchlickRoughness(float cosTheta, vec3 F0, float roughness)
{
    return F0 + (max(vec3(1.0 - roughness), F0) - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// The terms of the Cook-Torrance BRDF for one light direction L, as the text names them: the
// normal distribution D, the geometry term G, the Fresnel term F, the specular term
// D G F / (4 NdotV NdotL), the diffuse share kD = (1 - F)(1 - metallic), and NdotL.
struct CookTorrance
{
    float D;
    float G;
    vec3 F;
    vec3 specular;
    vec3 kD;
    float NdotL;
};

CookTorrance cookTorrance(vec3 N, vec3 V, vec3 L, vec3 albedo, float metallic, float roughness)
{
    CookTorrance t;
    vec3 H = normalize(V + L);
    vec3 F0 = mix(vec3(0.04), albedo, metallic);  // dielectrics reflect about 4% head-on

    t.D = DistributionGGX(N, H, roughness);
    t.G = GeometrySmith(N, V, L, roughness);
    t.F = fresnelSchlick(max(dot(H, V), 0.0), F0);

    float NdotV = max(dot(N, V), 0.0);
    t.NdotL = max(dot(N, L), 0.0);
    t.specular = t.D * t.G * t.F / (4.0 * NdotV * t.NdotL + 0.001);  // + 0.001: no division by 0

    vec3 kS = t.F;                                  // the reflected share is the Fresnel term...
    t.kD = (vec3(1.0) - kS) * (1.0 - metallic);    // ...the rest refracts; metals have none
    return t;
}

// Outgoing radiance from one light arriving along L with `radiance`: the reflectance equation's
// integrand for a single direction, (kD * albedo / PI + specular) * radiance * NdotL.
vec3 directLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 albedo, float metallic, float roughness)
{
    CookTorrance t = cookTorrance(N, V, L, albedo, metallic, roughness);
    return (t.kD * albedo / PI + t.specular) * radiance * t.NdotL;
}

// ---- glTF 2.0, Appendix B (the material the glTF samples 07 and 08 draw) ----
// Mirrored on the CPU by pbr::cpu::gltfDirectLight. The specification's BRDF differs from the
// text's above in three places: alpha = roughness^2 enters a height-correlated Smith visibility V
// (the masking-shadowing G divided by 4 NdotL NdotV); the diffuse lobe is weighted by 1 - F of the
// same half vector; and metallic does not blend colours, it blends two whole BRDFs (B.3.5):
//   dielectric = (1 - F_dielectric) c_diff / pi + F_dielectric D V,   F_dielectric from F0
//   metal      = F_metal D V,                                         F_metal from metalColor
//   f          = mix(dielectric, metal, metallic),    F(x) = x + (1 - x) (1 - VdotH)^5
// So at metallic 0.5 the diffuse keeps half of the dielectric's, not half of (1 - F) of a
// half-metal F0 (the simplified "c_diff = lerp(base, black, metallic)" that the specification
// dropped in 2024). A metallic-roughness material is F0 = 0.04, c_diff = metalColor = base
// colour; a specular-glossiness one is metallic 0 with its own c_diff and F0.

// GGX / Trowbridge-Reitz with alpha = roughness^2.
float D_GGX(float NdotH, float alpha)
{
    float a2 = alpha * alpha;
    float f = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * f * f);
}

// Smith's height-correlated masking-shadowing, divided by 4 NdotL NdotV.
float V_GGX(float NdotL, float NdotV, float alpha)
{
    float a2 = alpha * alpha;
    float ggxV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float ggxL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    float sum = ggxV + ggxL;
    return sum > 0.0 ? 0.5 / sum : 0.0;
}

// A perfect mirror (roughness 0) reflects a point light into an infinitely thin highlight, and
// GGX's peak becomes 0 / 0: alpha stays at or above this, as the CPU mirror's does.
const float MIN_GGX_ALPHA = 0.002;

// The terms of the glTF BRDF for one light direction L, as gltfDirectLight combines them (the
// term views show them apart): D, the visibility Vis = G / (4 NdotL NdotV), F of the dielectric
// and metal mixed, the diffuse and specular lobes (before radiance and NdotL), NdotL and NdotV.
// The dielectric's Fresnel runs from F0 head-on to F90 at grazing angles: 1 in the core material,
// KHR_materials_specular's strength in sample 10 (gltf_extensions.glsl, dielectricFresnel).
struct GltfBrdf
{
    float D;
    float Vis;
    vec3 F;
    vec3 diffuse;
    vec3 specular;
    float NdotL;
    float NdotV;
};

GltfBrdf gltfBrdfF90(vec3 N, vec3 V, vec3 L, vec3 diffuseColor, vec3 F0, float F90,
                     vec3 metalColor, float metallic, float roughness)
{
    GltfBrdf b;
    b.NdotL = clamp(dot(N, L), 0.0, 1.0);
    vec3 H = normalize(V + L);
    b.NdotV = clamp(dot(N, V), 0.0, 1.0);
    float NdotH = clamp(dot(N, H), 0.0, 1.0);
    float VdotH = clamp(dot(V, H), 0.0, 1.0);
    float alpha = max(roughness * roughness, MIN_GGX_ALPHA);
    float schlick = pow(1.0 - VdotH, 5.0);
    vec3 dielectricF = F0 + (F90 - F0) * schlick;
    vec3 metalF = metalColor + (1.0 - metalColor) * schlick;
    b.D = D_GGX(NdotH, alpha);
    b.Vis = V_GGX(b.NdotL, b.NdotV, alpha);
    b.F = mix(dielectricF, metalF, metallic);
    b.diffuse = (1.0 - metallic) * (1.0 - dielectricF) * diffuseColor / PI;
    b.specular = b.F * b.D * b.Vis;
    return b;
}

GltfBrdf gltfBrdf(vec3 N, vec3 V, vec3 L, vec3 diffuseColor, vec3 F0, vec3 metalColor,
                  float metallic, float roughness)
{
    return gltfBrdfF90(N, V, L, diffuseColor, F0, 1.0, metalColor, metallic, roughness);
}

// Radiance towards V from light arriving along L with `radiance`, for a surface given as its
// dielectric layer (diffuse colour c_diff under a specular layer of reflectance F0 at normal
// incidence), its metal's colour, and how metallic it is.
vec3 gltfDirectLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 diffuseColor, vec3 F0,
                     vec3 metalColor, float metallic, float roughness)
{
    if (dot(N, L) <= 0.0)
        return vec3(0.0);
    GltfBrdf b = gltfBrdf(N, V, L, diffuseColor, F0, metalColor, metallic, roughness);
    return (b.diffuse + b.specular) * radiance * b.NdotL;
}
