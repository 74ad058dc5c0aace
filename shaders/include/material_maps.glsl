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

// The maps at `uv` (09 tiles and offsets the texture coordinates first). A program built with
// NO_ALBEDO_MAP (NO_NORMAL_MAP, ...) defined reads a constant instead of that map (02's switches:
// mid grey, the mesh's own normal, metallic 0, roughness 0.5, ao 1), so that each map's part in
// the picture can be seen; without them this is the text's code.
Material readMaterialMapsAt(vec2 uv)
{
    Material m;
#ifdef NO_ALBEDO_MAP
    m.albedo = vec3(0.5);
#else
    m.albedo = texture(albedoMap, uv).rgb;  // already linear: no pow(2.2) needed
#endif
#ifdef NO_METALLIC_MAP
    m.metallic = 0.0;
#else
    m.metallic = texture(metallicMap, uv).r;
#endif
#ifdef NO_ROUGHNESS_MAP
    m.roughness = 0.5;
#else
    m.roughness = texture(roughnessMap, uv).r;
#endif
#ifdef NO_AO_MAP
    m.ao = 1.0;
#else
    m.ao = texture(aoMap, uv).r;
#endif
#ifdef NO_NORMAL_MAP
    vec3 tangentNormal = vec3(0.0, 0.0, 1.0);
#else
    vec3 tangentNormal = texture(normalMap, uv).xyz * 2.0 - 1.0;
#endif
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
