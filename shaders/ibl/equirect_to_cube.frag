#version 330 core
// An equirectangular environment onto one face of a cube map.
out vec4 FragColor;
in vec3 WorldPos;

uniform sampler2D equirectangularMap;

const vec2 invAtan = vec2(0.1591549, 0.3183099);  // 1 / (2 pi), 1 / pi

vec2 sampleSphericalMap(vec3 v)
{
    vec2 uv = vec2(atan(v.z, v.x), asin(v.y)) * invAtan + 0.5;
    // our images lie top row first (row 0 at t = 0) and the top row is straight up, so v = 1
    // (up) is t = 0; the text flips its images on load instead
    return vec2(uv.x, 1.0 - uv.y);
}

void main()
{
    FragColor = vec4(texture(equirectangularMap, sampleSphericalMap(normalize(WorldPos))).rgb, 1.0);
}
