// KHR_lights_punctual (glTF 2.0): directional, point and spot lights, each with colour x
// intensity, point and spot with the specification's range window, spot with its smooth cone.
// Mirrored on the CPU by pbr::cpu::punctualRadiance (common/math/brdf.h); uploaded by
// pbr::GltfRenderer::setLights (common/gltf/gltf_renderer.h).

const int MAX_PUNCTUAL_LIGHTS = 8;
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

struct PunctualLight
{
    int type;
    vec3 color;         // colour x intensity: candela (point, spot) or lux (directional)
    vec3 position;      // world space
    vec3 direction;     // world space, unit: where the light shines
    float range;        // 0: unlimited
    float innerConeCos;
    float outerConeCos;
};

uniform PunctualLight punctualLights[MAX_PUNCTUAL_LIGHTS];
uniform int punctualLightCount;

// The specification's window: inverse square, brought smoothly to zero at `range`.
float rangeAttenuation(float range, float distance)
{
    float inverseSquare = 1.0 / (distance * distance);
    if (range <= 0.0)
        return inverseSquare;
    float ratio = distance / range;
    return clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0) * inverseSquare;
}

// 1 inside the inner cone, 0 outside the outer one, the square of a linear ramp between.
float spotAttenuation(vec3 lightToPoint, vec3 spotDirection, float outerConeCos, float innerConeCos)
{
    float cd = dot(spotDirection, lightToPoint);
    float t = clamp((cd - outerConeCos) / max(0.001, innerConeCos - outerConeCos), 0.0, 1.0);
    return t * t;
}

// The radiance light i brings to `worldPos`, and the unit direction L towards it.
vec3 punctualRadiance(int i, vec3 worldPos, out vec3 L)
{
    PunctualLight light = punctualLights[i];
    if (light.type == LIGHT_DIRECTIONAL)
    {
        L = -light.direction;
        return light.color;
    }
    vec3 toLight = light.position - worldPos;
    float distance = length(toLight);
    L = toLight / distance;
    vec3 radiance = light.color * rangeAttenuation(light.range, distance);
    if (light.type == LIGHT_SPOT)
        radiance *= spotAttenuation(-L, light.direction, light.outerConeCos, light.innerConeCos);
    return radiance;
}
