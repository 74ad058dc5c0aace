// Tangent-space normal maps (OpenGL convention: green points to the image's top).
// Two ways to the tangent frame; both return the world-space normal.

// From the mesh: the vertex tangent (xyz along +u, w the handedness, see common/gl/mesh.h),
// re-orthogonalised against the interpolated normal (Gram-Schmidt).
vec3 normalFromMapWithTangent(vec3 tangentNormal, vec3 normal, vec4 tangent)
{
    vec3 N = normalize(normal);
    vec3 T = normalize(tangent.xyz - dot(tangent.xyz, N) * N);
    vec3 B = cross(N, T) * tangent.w;
    return normalize(mat3(T, B, N) * tangentNormal);
}

// From screen-space derivatives of position and uv, as LearnOpenGL's text does: no tangent
// attribute needed, but the frame is flat per pixel quad and breaks down where uv derivatives
// vanish or mirror. B is flipped because our images lie top row at v = 0.
vec3 normalFromMapWithDerivatives(vec3 tangentNormal, vec3 normal, vec3 worldPos, vec2 uv)
{
    vec3 Q1 = dFdx(worldPos);
    vec3 Q2 = dFdy(worldPos);
    vec2 st1 = dFdx(uv);
    vec2 st2 = dFdy(uv);
    vec3 N = normalize(normal);
    vec3 T = normalize(Q1 * st2.t - Q2 * st1.t);
    vec3 B = -normalize(cross(N, T));
    return normalize(mat3(T, B, N) * tangentNormal);
}
