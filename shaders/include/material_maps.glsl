// The five maps of a PBR material folder (see common/gl/texture.h), read at TexCoords. The
// including shader declares the inputs TexCoords, WorldPos, Normal and Tangent.
#include "normal_mapping.glsl"

// albedoMap is an sRGB texture, so the sampler returns linear values; aoMap holds linear data
uniform sampler2D albedoMap;
uniform sampler2D normalMap;
uniform sampler2D metallicMap;
uniform sampler2D roughnessMap;
uniform sampler2D aoMap;
uniform bool useDerivativeTangents;  // the text's screen-space tangent frame instead of the mesh's

struct Material
{
    vec3 albedo;
    float metallic;
    float roughness;
    float ao;
    vec3 N;  // the world-space normal, from the normal map
};

// The maps at `uv` (09 tiles and offsets the texture coordinates first).
Material readMaterialMapsAt(vec2 uv)
{
    Material m;
    m.albedo = texture(albedoMap, uv).rgb;  // already linear: no pow(2.2) needed
    m.metallic = texture(metallicMap, uv).r;
    m.roughness = texture(roughnessMap, uv).r;
    m.ao = texture(aoMap, uv).r;
    vec3 tangentNormal = texture(normalMap, uv).xyz * 2.0 - 1.0;
    if (useDerivativeTangents)
        m.N = normalFromMapWithDerivatives(tangentNormal, Normal, WorldPos, uv);
    else
        m.N = normalFromMapWithTangent(tangentNormal, Normal, Tangent);
    return m;
}

Material readMaterialMaps()
{
    return readMaterialMapsAt(TexCoords);
}
