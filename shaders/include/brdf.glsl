// The Cook-Torrance BRDF of LearnOpenGL's PBR chapters, written once for every sample.
// Mirrored on the CPU by common/brdf.cpp (same names), which the reference tests compare against.

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

// Outgoing radiance from one light arriving along L with `radiance`: the reflectance equation's
// integrand for a single direction, (kD * albedo / PI + specular) * radiance * NdotL.
vec3 directLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 albedo, float metallic, float roughness)
{
    vec3 H = normalize(V + L);
    vec3 F0 = mix(vec3(0.04), albedo, metallic);  // dielectrics reflect about 4% head-on

    float NDF = DistributionGGX(N, H, roughness);
    float G = GeometrySmith(N, V, L, roughness);
    vec3 F = fresnelSchlick(max(dot(H, V), 0.0), F0);

    float NdotV = max(dot(N, V), 0.0);
    float NdotL = max(dot(N, L), 0.0);
    vec3 specular = NDF * G * F / (4.0 * NdotV * NdotL + 0.001);  // + 0.001: no division by zero

    vec3 kS = F;                                // the reflected share is the Fresnel term...
    vec3 kD = (vec3(1.0) - kS) * (1.0 - metallic);  // ...the rest refracts; metals have none
    return (kD * albedo / PI + specular) * radiance * NdotL;
}

// ---- glTF 2.0, Appendix B (the material the glTF samples 07 and 08 draw) ----
// Mirrored on the CPU by pbr::cpu::gltfDirectLight. The specification's BRDF differs from the
// text's above in two places: alpha = roughness^2 enters a height-correlated Smith visibility V
// (the masking-shadowing G divided by 4 NdotL NdotV), and the diffuse lobe is weighted by 1 - F
// of the same half vector. Its "implementation" form (B.3.5) takes a material as two colours,
// which is what lets the metallic-roughness and specular-glossiness workflows share one path:
//   f_diffuse = (1 - F) c_diff / pi,  f_specular = F D V,  F = F0 + (1 - F0) (1 - VdotH)^5.

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

// Radiance towards V from light arriving along L with `radiance`, for a surface given as its
// diffuse colour c_diff and its reflectance at normal incidence F0.
vec3 gltfDirectLight(vec3 N, vec3 V, vec3 L, vec3 radiance, vec3 diffuseColor, vec3 F0,
                     float roughness)
{
    float NdotL = clamp(dot(N, L), 0.0, 1.0);
    if (NdotL <= 0.0)
        return vec3(0.0);
    vec3 H = normalize(V + L);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    float NdotH = clamp(dot(N, H), 0.0, 1.0);
    float VdotH = clamp(dot(V, H), 0.0, 1.0);
    float alpha = max(roughness * roughness, MIN_GGX_ALPHA);
    vec3 F = F0 + (1.0 - F0) * pow(1.0 - VdotH, 5.0);
    vec3 diffuse = (1.0 - F) * diffuseColor / PI;
    vec3 specular = F * D_GGX(NdotH, alpha) * V_GGX(NdotL, NdotV, alpha);
    return (diffuse + specular) * radiance * NdotL;
}
