// The ambient light of the split-sum IBL (LearnOpenGL PBR / IBL / Specular IBL): the diffuse
// part from the irradiance map, the specular part from the prefiltered environment at the
// roughness's mip level times the BRDF LUT's scale and bias to F0. Needs brdf.glsl first.

uniform samplerCube irradianceMap;  // irradiance / pi of the environment
uniform samplerCube prefilterMap;   // mip m: the environment prefiltered for roughness m / maxLod
uniform sampler2D brdfLUT;          // x = NdotV, y = roughness: (scale, bias) to F0
// The prefiltered map's last mip level (the text's MAX_REFLECTION_LOD, 4 for five levels), set
// from the map itself by pbr::useIblMaps, never by hand.
uniform float prefilterMaxLod;

vec3 ambientLight(vec3 N, vec3 V, vec3 albedo, float metallic, float roughness, float ao)
{
    float NdotV = max(dot(N, V), 0.0);
    vec3 R = reflect(-V, N);
    vec3 F0 = mix(vec3(0.04), albedo, metallic);
    vec3 F = fresnelSchlickRoughness(NdotV, F0, roughness);
    vec3 kS = F;
    vec3 kD = (1.0 - kS) * (1.0 - metallic);

    vec3 irradiance = texture(irradianceMap, N).rgb;
    vec3 diffuse = irradiance * albedo;

    vec3 prefilteredColor = textureLod(prefilterMap, R, roughness * prefilterMaxLod).rgb;
    vec2 envBRDF = texture(brdfLUT, vec2(NdotV, roughness)).rg;
    vec3 specular = prefilteredColor * (F * envBRDF.x + envBRDF.y);

    return (kD * diffuse + specular) * ao;
}
