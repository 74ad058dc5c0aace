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
