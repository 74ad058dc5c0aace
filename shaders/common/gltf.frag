#version 330 core
// The cookbook's glTF PBR recipes ("metallic-roughness", sample 07; "specular-glossiness",
// sample 08), as the glTF 2.0 specification defines the material: image-based light (the exact
// split sum of 05's maps) times occlusion, plus the file's punctual lights through the
// Appendix B BRDF, plus emission; then exposure and a tone mapper. Either workflow arrives as one
// SurfaceMaterial (gltf_material.glsl). The render target is sRGB: this writes linear values and
// the GL encodes them.
out vec4 FragColor;
in vec3 WorldPos;
in vec3 Normal;
in vec4 Tangent;
in vec2 TexCoords0;
in vec2 TexCoords1;
in vec4 VertexColor;

uniform vec3 camPos;
uniform bool useIbl;
uniform bool usePunctual;
uniform int toneMapper;  // TONEMAP_* of tonemap.glsl
uniform float exposure;

#include "brdf.glsl"
#include "ibl_ambient.glsl"
#include "punctual_lights.glsl"
#include "gltf_material.glsl"
#include "tonemap.glsl"
#include "views.glsl"
#include "gltf_views.glsl"

void main()
{
    SurfaceMaterial m = readGltfMaterial();
    vec3 color = m.baseColor;
    if (!unlit)
    {
        vec3 V = normalize(camPos - WorldPos);
        color = m.emissive;
        if (usePunctual)
        {
            for (int i = 0; i < punctualLightCount; ++i)
            {
                vec3 L;
                vec3 radiance = punctualRadiance(i, WorldPos, L);
                color += gltfDirectLight(m.N, V, L, radiance, m.diffuseColor, m.F0, m.baseColor,
                                         m.metallic, m.roughness);
            }
        }
        if (useIbl)
            color += ambientLightGltf(m.N, V, m.diffuseColor, m.F0, m.baseColor, m.metallic,
                                      m.roughness) * m.occlusion;
    }
    FragColor = vec4(toneMap(color, toneMapper, exposure), m.alpha);
#ifdef TERM_VIEWS  // --view: one input or term of the equation instead (gltf_views.glsl)
    FragColor.rgb = gltfView(termView, m, normalize(camPos - WorldPos));
#endif
}
