// The ambient light of the split-sum IBL (Karis, "Real Shading in Unreal Engine 4"; LearnOpenGL
// PBR / IBL / Specular IBL): the diffuse part from the irradiance map, the specular part from the
// prefiltered environment at the roughness's mip level times the BRDF LUT's scale and bias to
// F0. Two forms, chosen by `exactSplitSum`:
//
//   the text's (LearnOpenGL, kept so that 04 and 05 teach it and match its pictures):
//     F = fresnelSchlickRoughness(NdotV, F0, roughness); kD = (1 - F) (1 - metallic)
//     ambient = kD irradiance albedo + prefiltered (F scale + bias)
//   the split sum as its derivation has it (the form the glTF samples use):
//     E = F0 scale + bias    (the specular lobe's directional albedo)
//     ambient = (1 - metallic) albedo irradiance (1 - E_dielectric) + prefiltered E
//
// The LUT's scale already integrates Fresnel over the lobe (the factor 1 - (1 - VdotH)^5 inside
// it): multiplying it by a Fresnel term of the view angle again, as the text does, counts Fresnel
// twice, and the diffuse weight 1 - F does not give back what that specular takes. In a white
// furnace (environment 1, albedo 1) a smooth dielectric comes out up to 1.24 towards its rim
// with the text's form, where the exact form gives 1 everywhere: light not reflected by the
// specular lobe (1 - E) is what reaches the diffuse layer. Needs brdf.glsl first.

uniform samplerCube irradianceMap;  // irradiance / pi of the environment
uniform samplerCube prefilterMap;   // mip m: the environment prefiltered for roughness m / maxLod
uniform sampler2D brdfLUT;          // x = NdotV, y = roughness: (scale, bias) to F0
// The environment itself: the mirror end of the prefiltered range. The prefiltered map's level 0
// is only 128^2, magnified on a smooth sphere into stair-stepped reflections and sparkling
// single texels of sun on its rim; below the first rough level the reflection blends from the
// environment, read at the mip level the screen asks for, to level 1, as the texture unit would
// have blended level 0 to level 1.
uniform samplerCube environmentMap;
// The prefiltered map's last mip level (the text's MAX_REFLECTION_LOD, 4 for five levels), set
// from the map itself by pbr::useIblMaps, never by hand.
uniform float prefilterMaxLod;
uniform bool exactSplitSum;  // false: the text's form (04, 05 by default); true: the exact one

// The three reads of the split sum at one surface point.
struct SplitSumReads
{
    float NdotV;
    vec3 irradiance;        // at N
    vec3 prefilteredColor;  // along R = reflect(-V, N), at the roughness's mip level
    vec2 envBRDF;           // the LUT's (scale, bias) at (NdotV, roughness)
};

SplitSumReads readSplitSum(vec3 N, vec3 V, float roughness)
{
    SplitSumReads s;
    s.NdotV = max(dot(N, V), 0.0);
    vec3 R = reflect(-V, N);
    s.irradiance = texture(irradianceMap, N).rgb;
    float lod = roughness * prefilterMaxLod;
    // R's screen-space derivatives are taken for every fragment (derivatives need all of them);
    // the environment itself is read only where the blend needs it
    vec3 dRdx = dFdx(R), dRdy = dFdy(R);
    if (lod < 1.0)
        s.prefilteredColor = mix(textureGrad(environmentMap, R, dRdx, dRdy).rgb,
                                 textureLod(prefilterMap, R, 1.0).rgb, lod);
    else
        s.prefilteredColor = textureLod(prefilterMap, R, lod).rgb;
    s.envBRDF = texture(brdfLUT, vec2(s.NdotV, roughness)).rg;
    return s;
}

// The ambient light's two parts before occlusion, and the reads they come from: the term views
// (views.glsl) show them apart, the picture their sum (ambientLight).
struct AmbientTerms
{
    SplitSumReads reads;
    vec3 diffuse;
    vec3 specular;
    vec3 kS, kD;           // the weights: what the specular part takes, what the diffuse part gets
    vec3 specularFactor;   // on the prefiltered radiance
};

AmbientTerms ambientTerms(vec3 N, vec3 V, vec3 albedo, float metallic, float roughness)
{
    AmbientTerms t;
    SplitSumReads s = readSplitSum(N, V, roughness);
    t.reads = s;
    float NdotV = s.NdotV;
    vec3 F0 = mix(vec3(0.04), albedo, metallic);
    vec3 irradiance = s.irradiance;
    vec3 prefilteredColor = s.prefilteredColor;
    vec2 envBRDF = s.envBRDF;

    if (exactSplitSum)
    {
        // glTF's mix of a dielectric (F0 0.04 over a diffuse base) and a metal (F0 = albedo).
        float dielectricE = 0.04 * envBRDF.x + envBRDF.y;
        vec3 E = F0 * envBRDF.x + envBRDF.y;
        t.diffuse = (1.0 - metallic) * albedo * irradiance * (1.0 - dielectricE);
        t.specular = prefilteredColor * E;
        t.kS = E;
        t.kD = vec3((1.0 - metallic) * (1.0 - dielectricE));
        t.specularFactor = E;
        return t;
    }
    vec3 F = fresnelSchlickRoughness(NdotV, F0, roughness);
    vec3 kS = F;
    vec3 kD = (1.0 - kS) * (1.0 - metallic);
    vec3 diffuse = irradiance * albedo;
    t.diffuse = kD * diffuse;
    t.specular = prefilteredColor * (F * envBRDF.x + envBRDF.y);
    t.kS = kS;
    t.kD = kD;
    t.specularFactor = F * envBRDF.x + envBRDF.y;
    return t;
}

vec3 ambientLight(vec3 N, vec3 V, vec3 albedo, float metallic, float roughness, float ao)
{
    AmbientTerms t = ambientTerms(N, V, albedo, metallic, roughness);
    return (t.diffuse + t.specular) * ao;
}

// The glTF samples' image-based light: the exact split sum above for the specification's mix of
// a dielectric and a metal BRDF (brdf.glsl, gltfDirectLight), with or without the energy that the
// single-scattering lobe loses to light bouncing between microfacets more than once.
//
// Single scattering: a lobe of reflectance F0 reflects E_ss = F0 scale + bias of the environment
// (the LUT's directional albedo), and a dielectric's diffuse layer gets what it leaves, 1 - E_ss.
// A white metal then returns only scale + bias of a white environment: facing the viewer, 0.89
// of it at roughness 0.5, 0.31 at roughness 1.
// Multiple scattering (Fdez-Aguera, "A Multiple-Scattering Microfacet Model for Real-Time
// Image-based Lighting", JCGT 2019), the specification's recommendation: the lost share of a
// white lobe, E_ms = 1 - (scale + bias), comes back after further bounces, each tinted by the
// average Fresnel F_avg = F0 + (1 - F0) / 21, a geometric series:
//   E_ms(F0) = E_ms F_avg E_ss(F0) / (1 - F_avg E_ms),
// spread over the hemisphere (so lit by the irradiance, not the prefiltered lobe). A white metal
// in a white furnace returns the environment exactly, at every roughness.
uniform bool multipleScattering;

// The radiance a lobe of reflectance F0 (head-on) to F90 (grazing) returns: single-scattered
// from the prefiltered environment, multiple-scattered (when on) from the irradiance; `albedo`
// gets the whole share, `multipleRadiance` the multiple-scattered radiance alone.
vec3 specularIblF90(vec3 F0, float F90, SplitSumReads s, out vec3 albedo, out vec3 multipleRadiance)
{
    vec3 single = F0 * s.envBRDF.x + F90 * s.envBRDF.y;
    vec3 multiple = vec3(0.0);
    if (multipleScattering)
    {
        float lost = 1.0 - (s.envBRDF.x + s.envBRDF.y);
        vec3 averageF = F0 + (F90 - F0) / 21.0;
        multiple = lost * averageF * single / (1.0 - averageF * lost);
    }
    albedo = single + multiple;
    multipleRadiance = multiple * s.irradiance;
    return single * s.prefilteredColor + multipleRadiance;
}

vec3 specularIbl(vec3 F0, SplitSumReads s, out vec3 albedo, out vec3 multipleRadiance)
{
    return specularIblF90(F0, 1.0, s, albedo, multipleRadiance);
}

// The glTF image-based light's parts before occlusion and the reads they come from: the
// dielectric's diffuse layer and specular lobe, and the metal's lobe (the term views show them
// apart, ambientLightGltf mixes them). c_diff, F0 and metalColor as gltfDirectLight takes them.
struct GltfAmbientTerms
{
    SplitSumReads reads;
    vec3 diffuse;
    vec3 dielectricSpecular;
    vec3 metal;
    vec3 dielectricMultiple, metalMultiple;  // the lobes' multiple-scattered radiance (in the above)
};

GltfAmbientTerms gltfAmbientTerms(vec3 N, vec3 V, vec3 diffuseColor, vec3 F0, vec3 metalColor,
                                  float roughness)
{
    GltfAmbientTerms t;
    t.reads = readSplitSum(N, V, roughness);
    vec3 dielectricAlbedo, metalAlbedo;
    t.dielectricSpecular = specularIbl(F0, t.reads, dielectricAlbedo, t.dielectricMultiple);
    t.metal = specularIbl(metalColor, t.reads, metalAlbedo, t.metalMultiple);
    t.diffuse = diffuseColor * t.reads.irradiance * (1.0 - dielectricAlbedo);
    return t;
}

// Occlusion is the caller's.
vec3 ambientLightGltf(vec3 N, vec3 V, vec3 diffuseColor, vec3 F0, vec3 metalColor, float metallic,
                      float roughness)
{
    GltfAmbientTerms t = gltfAmbientTerms(N, V, diffuseColor, F0, metalColor, roughness);
    vec3 dielectric = t.diffuse + t.dielectricSpecular;
    return mix(dielectric, t.metal, metallic);
}
