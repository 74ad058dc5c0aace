// The Overload engine's five light types, read from one buffer (sample 09). Each light is the
// engine's mat4, here a struct of four vec4 columns mirrored by pbr::PackedLight
// (common/math/light_block.h, which documents every slot); the block by pbr::LightBlock. Mirrored
// on the CPU by pbr::cpu::shadeLightTypes (common/math/brdf.cpp). Needs brdf.glsl.

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

// Outgoing radiance at `position`: the direct lights through directLight (brdf.glsl) plus the
// ambient volumes that contain the point, x albedo x ao. Linear, before tone mapping.
vec3 shadeLights(vec3 position, vec3 N, vec3 V, vec3 albedo, float metallic, float roughness,
                 float ao)
{
    vec3 Lo = vec3(0.0);
    vec3 ambient = vec3(0.0);
    for (int i = 0; i < lightCount; ++i)
    {
        Light light = lights[i];
        int type = int(light.typeCutoffOuterIntensity.x);
        vec3 color = light.colorQuadratic.rgb * light.typeCutoffOuterIntensity.w;
        if (type == LIGHT_AMBIENT_BOX)
        {
            if (insideAmbientBox(light, position))
                ambient += color;
            continue;
        }
        if (type == LIGHT_AMBIENT_SPHERE)
        {
            if (insideAmbientSphere(light, position))
                ambient += color;
            continue;
        }
        vec3 L;
        float coefficient = 1.0;
        if (type == LIGHT_DIRECTIONAL)
        {
            L = normalize(-light.forwardLinear.xyz);
        }
        else
        {
            vec3 toLight = light.positionConstant.xyz - position;
            L = normalize(toLight);
            coefficient = lightAttenuation(light, length(toLight));
            if (type == LIGHT_SPOT)
                coefficient *= spotCone(light, L);
        }
        Lo += directLight(N, V, L, color * coefficient, albedo, metallic, roughness);
    }
    return ambient * albedo * ao + Lo;
}
