// The Overload engine's five light types, read from one buffer (sample 09). Each light is the
// engine's mat4, here a struct of four vec4 columns mirrored by pbr::PackedLight
// (common/math/light_block.h, which documents every slot); the block by pbr::LightBlock. Mirrored
// on the CPU by pbr::cpu::shadeLightTypes (common/math/brdf.cpp). Needs brdf.glsl, and for the
// term views views.glsl and tonemap.glsl before it.

const int MAX_LIGHTS = 255;  // pbr::LightBlock::kMaxLights: 16 KiB, the block size GL 3.3 guarantees

const int LIGHT_POINT = 0;
const int LIGHT_DIRECTIONAL = 1;
const int LIGHT_SPOT = 2;
const int LIGHT_AMBIENT_BOX = 3;
const int LIGHT_AMBIENT_SPHERE = 4;

struct Light
{
    vec4 positionConstant;          // xyz position or centre; w constant (box: half x; sphere: radius)
    vec4 forwardLinear;             // xyz forward; w linear (box: half y)
    vec4 colorQuadratic;            // rgb colour; w quadratic (box: half z)
    vec4 typeCutoffOuterIntensity;  // type, cut-off (deg), outer (deg, added), intensity
};

layout(std140) uniform LightBlock
{
    int lightCount;
    Light lights[MAX_LIGHTS];
};

// 1 / (constant + linear d + quadratic d^2): the engine's (and LearnOpenGL's) attenuation.
float lightAttenuation(Light light, float d)
{
    return 1.0 / (light.positionConstant.w + light.forwardLinear.w * d +
                  light.colorQuadratic.w * d * d);
}

// The spot's cone: 1 inside the cut-off angle, 0 beyond cut-off + outer, linear in the cosine
// between them.
float spotCone(Light light, vec3 toLight)
{
    float cutOff = cos(radians(light.typeCutoffOuterIntensity.y));
    float outerCutOff =
        cos(radians(light.typeCutoffOuterIntensity.y + light.typeCutoffOuterIntensity.z));
    float theta = dot(toLight, normalize(-light.forwardLinear.xyz));
    return clamp((theta - outerCutOff) / (cutOff - outerCutOff), 0.0, 1.0);
}

bool insideAmbientBox(Light light, vec3 p)
{
    vec3 d = abs(p - light.positionConstant.xyz);
    vec3 halfSize = vec3(light.positionConstant.w, light.forwardLinear.w, light.colorQuadratic.w);
    return all(lessThan(d, halfSize));
}

bool insideAmbientSphere(Light light, vec3 p)
{
    return distance(p, light.positionConstant.xyz) < light.positionConstant.w;
}

// What one light brings to `position`: a direct light's radiance there (attenuation and cone
// included) from the unit direction it sets in L; an ambient volume's colour where the volume
// holds the point, else nothing.
vec3 lightRadiance(Light light, vec3 position, out vec3 L)
{
    int type = int(light.typeCutoffOuterIntensity.x);
    vec3 color = light.colorQuadratic.rgb * light.typeCutoffOuterIntensity.w;
    L = vec3(0.0, 1.0, 0.0);
    if (type == LIGHT_AMBIENT_BOX)
        return insideAmbientBox(light, position) ? color : vec3(0.0);
    if (type == LIGHT_AMBIENT_SPHERE)
        return insideAmbientSphere(light, position) ? color : vec3(0.0);
    if (type == LIGHT_DIRECTIONAL)
    {
        L = normalize(-light.forwardLinear.xyz);
        return color;
    }
    vec3 toLight = light.positionConstant.xyz - position;
    L = normalize(toLight);
    float coefficient = lightAttenuation(light, length(toLight));
    if (type == LIGHT_SPOT)
        coefficient *= spotCone(light, L);
    return color * coefficient;
}

bool isAmbientVolume(Light light)
{
    int type = int(light.typeCutoffOuterIntensity.x);
    return type == LIGHT_AMBIENT_BOX || type == LIGHT_AMBIENT_SPHERE;
}

#ifdef TERM_VIEWS
// What the term views take from the loop below, gathered as it runs: the direct lights' terms,
// summed over those that reach the point (above its horizon, and inside a spot's cone), and the
// two kinds of light apart (lightTypesView).
DirectSums viewSums;
vec3 viewDirect;
vec3 viewAmbient;
float viewAttenuation;  // summed over the point and spot lights, at any side of the horizon
float viewCone;         // summed over the spot lights
#endif

// Outgoing radiance at `position`: the direct lights through directLight (brdf.glsl) plus the
// ambient volumes that contain the point, x albedo x ao. Linear, before tone mapping.
vec3 shadeLights(vec3 position, vec3 N, vec3 V, vec3 albedo, float metallic, float roughness,
                 float ao)
{
    vec3 Lo = vec3(0.0);
    vec3 ambient = vec3(0.0);
#ifdef TERM_VIEWS
    viewSums = noDirectSums();
    viewAttenuation = 0.0;
    viewCone = 0.0;
#endif
    for (int i = 0; i < lightCount; ++i)
    {
        vec3 L;
        vec3 radiance = lightRadiance(lights[i], position, L);
        if (isAmbientVolume(lights[i]))
        {
            ambient += radiance;
            continue;
        }
        Lo += directLight(N, V, L, radiance, albedo, metallic, roughness);
#ifdef TERM_VIEWS
        if (radiance != vec3(0.0))
            addDirectTerms(viewSums, N, V, L, albedo, metallic, roughness);
        int type = int(lights[i].typeCutoffOuterIntensity.x);
        if (type == LIGHT_POINT || type == LIGHT_SPOT)
            viewAttenuation += lightAttenuation(lights[i], distance(lights[i].positionConstant.xyz, position));
        if (type == LIGHT_SPOT)
            viewCone += spotCone(lights[i], L);
#endif
    }
#ifdef TERM_VIEWS
    viewDirect = Lo;
    viewAmbient = ambient;
#endif
    return ambient * albedo * ao + Lo;
}

#ifdef TERM_VIEWS
// 09's term views (views.glsl), after shadeLights has run at this point: the inputs; the direct
// lights' terms; the direct light alone and the ambient volumes' light alone (x albedo x ao),
// each through the picture's Reinhard and gamma; the attenuation as x / (1 + x) and the spot's
// cone as it is.
vec3 lightTypesView(int which, vec3 N, vec3 albedo, float metallic, float roughness, float ao)
{
    if (which == VIEW_AMBIENT)
        return gammaCorrect(reinhard(viewAmbient * albedo * ao));
    if (which == VIEW_ATTENUATION)
        return viewCompress(vec3(viewAttenuation));
    if (which == VIEW_CONE)
        return vec3(viewCone);
    return directView(which, albedo, N, metallic, roughness, ao, viewSums,
                      gammaCorrect(reinhard(viewDirect)));
}
#endif
