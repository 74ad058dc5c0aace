// The term views (--view NAME): instead of the picture, one input or one term of the lesson's
// equation, selected by the uniform `termView`. Compiled in only when the sample builds its
// shaders with TERM_VIEWS defined (pbr::viewDefines), that is for any view but the picture:
// without it this file is empty and the picture's program is the lesson's own. The
// numbers mirror pbr::View (common/app/views.h; a unit test holds the two together), and each
// view's formula and encoding is defined in the README of the samples that have it:
//   inputs as they are (albedo, metallic, roughness, ao, F0 = mix(0.04, albedo, metallic)), the
//   world-space normal as 0.5 + 0.5 N; a light-dependent term (D, G, F, the specular term, the
//   diffuse term, NdotL) summed over the lights above the surface's horizon (NdotL > 0), then
//   shown as x / (1 + x); the direct light alone through the sample's own tone mapping. The
//   image-based light's reads (irradiance, the prefiltered radiance) and the two parts of the
//   ambient light as x / (1 + x), the LUT's (scale, bias) as they are, the ambient light alone
//   through the sample's own tone mapping.
// Needs brdf.glsl.
#ifdef TERM_VIEWS
uniform int termView;  // not `view`: the vertex shaders' view matrix has that name

const int VIEW_FINAL = 0;
const int VIEW_ALBEDO = 1;
const int VIEW_NORMAL = 2;
const int VIEW_METALLIC = 3;
const int VIEW_ROUGHNESS = 4;
const int VIEW_AO = 5;
const int VIEW_F0 = 6;
const int VIEW_D = 7;
const int VIEW_G = 8;
const int VIEW_F = 9;
const int VIEW_SPECULAR = 10;
const int VIEW_DIFFUSE = 11;
const int VIEW_NDOTL = 12;
const int VIEW_DIRECT = 13;
const int VIEW_IRRADIANCE = 14;
const int VIEW_PREFILTERED = 15;
const int VIEW_LUT = 16;
const int VIEW_AMBIENT_DIFFUSE = 17;
const int VIEW_AMBIENT_SPECULAR = 18;
const int VIEW_AMBIENT = 19;
const int VIEW_BASE_COLOR = 20;  // the glTF samples' names for their inputs (gltf_views.glsl)
const int VIEW_OCCLUSION = 21;
const int VIEW_EMISSIVE = 22;
const int VIEW_ATTENUATION = 23;
const int VIEW_CONE = 24;
const int VIEW_KS = 25;
const int VIEW_KD = 26;
const int VIEW_F_SCALE_BIAS = 27;
const int VIEW_VISIBILITY = 28;
const int VIEW_MULTIPLE_SCATTERING = 29;
const int VIEW_CLEARCOAT = 30;  // sample 10's layers (gltf.frag's layeredView)
const int VIEW_SHEEN = 31;
const int VIEW_SHEEN_SCALING = 32;
const int VIEW_TRANSMISSION = 33;
const int VIEW_TRANSMITTED = 34;
const int VIEW_CLEARCOAT_NORMAL = 35;
const int VIEW_VOLUME_ATTENUATION = 36;

// The light-dependent terms, summed over the lights (see addDirectTerms).
struct DirectSums
{
    float D;
    float G;
    vec3 F;
    vec3 specular;
    vec3 diffuse;
    float NdotL;
};

DirectSums noDirectSums()
{
    return DirectSums(0.0, 0.0, vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
}

// Adds one light's terms when it is above the horizon: the very terms directLight combines.
void addDirectTerms(inout DirectSums sums, vec3 N, vec3 V, vec3 L, vec3 albedo, float metallic,
                    float roughness)
{
    CookTorrance t = cookTorrance(N, V, L, albedo, metallic, roughness);
    if (t.NdotL <= 0.0)
        return;
    sums.D += t.D;
    sums.G += t.G;
    sums.F += t.F;
    sums.specular += t.specular;
    sums.diffuse += t.kD * albedo / PI;
    sums.NdotL += t.NdotL;
}

// An unbounded value shown in [0, 1): x / (1 + x).
uniform float viewGain;  // --gain: multiplies what is compressed (1: as it is)

vec3 viewCompress(vec3 x)
{
    x *= viewGain;
    return x / (1.0 + x);
}

// What a view shows, as it goes to the framebuffer of the direct-light samples (no sRGB
// encoding by the GL): `directColor` is the direct light alone, tone mapped as the picture is.
vec3 directView(int which, vec3 albedo, vec3 N, float metallic, float roughness, float ao,
                DirectSums sums, vec3 directColor)
{
    if (which == VIEW_ALBEDO) return albedo;
    if (which == VIEW_NORMAL) return 0.5 + 0.5 * N;
    if (which == VIEW_METALLIC) return vec3(metallic);
    if (which == VIEW_ROUGHNESS) return vec3(roughness);
    if (which == VIEW_AO) return vec3(ao);
    if (which == VIEW_F0) return mix(vec3(0.04), albedo, metallic);
    if (which == VIEW_D) return viewCompress(vec3(sums.D));
    if (which == VIEW_G) return viewCompress(vec3(sums.G));
    if (which == VIEW_F) return viewCompress(sums.F);
    if (which == VIEW_SPECULAR) return viewCompress(sums.specular);
    if (which == VIEW_DIFFUSE) return viewCompress(sums.diffuse);
    if (which == VIEW_NDOTL) return viewCompress(vec3(sums.NdotL));
    if (which == VIEW_DIRECT) return directColor;
    return vec3(1.0, 0.0, 1.0);  // a view this sample does not have: never asked for (--view)
}

// What an image-based light's view shows (04, 05), and `otherwise` for any other view. The reads
// at this point: `irradiance` at N, `prefiltered` along R at the roughness's level, the LUT's
// (scale, bias); the ambient light's two parts, occlusion included, which sum to the ambient
// light (`ambientDiffuse` + `ambientSpecular`, zero both when the sample's image-based light is
// off), and `ambientColor`, the ambient light alone as the picture tone maps it.
vec3 iblView(int which, vec3 irradiance, vec3 prefiltered, vec2 lut, vec3 ambientDiffuse,
             vec3 ambientSpecular, vec3 ambientColor, vec3 otherwise)
{
    if (which == VIEW_IRRADIANCE) return viewCompress(irradiance);
    if (which == VIEW_PREFILTERED) return viewCompress(prefiltered);
    if (which == VIEW_LUT) return vec3(lut, 0.0);
    if (which == VIEW_AMBIENT_DIFFUSE) return viewCompress(ambientDiffuse);
    if (which == VIEW_AMBIENT_SPECULAR) return viewCompress(ambientSpecular);
    if (which == VIEW_AMBIENT) return ambientColor;
    return otherwise;
}

// The ambient light's weights (04, 05), as they are, and `otherwise` for any other view: kS, what
// the specular part takes; kD, what the diffuse part gets; the specular part's factor on the
// prefiltered radiance (the text's F scale + bias; the exact split sum's F0 scale + bias).
vec3 ambientWeightView(int which, vec3 kS, vec3 kD, vec3 specularFactor, vec3 otherwise)
{
    if (which == VIEW_KS) return kS;
    if (which == VIEW_KD) return kD;
    if (which == VIEW_F_SCALE_BIAS) return specularFactor;
    return otherwise;
}
#endif  // TERM_VIEWS
