// The glTF samples' term views (--view NAME; views.glsl's numbers, defined in 07's README): the
// material's inputs as the specification reads them; the punctual lights' terms of the
// Appendix B BRDF (gltfBrdf), summed over the lights that reach the point (above its horizon,
// inside a spot's cone and a light's range); the image-based light's reads and parts
// (gltfAmbientTerms), occlusion included; the direct and the ambient light alone through the
// picture's exposure and tone mapper. Needs views.glsl, brdf.glsl, ibl_ambient.glsl,
// punctual_lights.glsl, gltf_material.glsl and tonemap.glsl, and the including shader's uniforms
// usePunctual, useIbl, toneMapper and exposure.
//
// The target is sRGB: the GL encodes what the shader writes. A value shown as it is, v, is
// written as the linear value that encodes to v, so that the picture's bytes are 255 v.
#ifdef TERM_VIEWS
vec3 encodedAs(vec3 v)  // the linear value the sRGB encoding takes to v
{
    v = clamp(v, 0.0, 1.0);
    return mix(v / 12.92, pow((v + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), v));
}

vec3 gltfView(int which, SurfaceMaterial m, vec3 V)
{
    if (which == VIEW_BASE_COLOR) return encodedAs(m.baseColor);
    if (which == VIEW_NORMAL) return encodedAs(0.5 + 0.5 * m.N);
    if (which == VIEW_METALLIC) return encodedAs(vec3(m.metallic));
    if (which == VIEW_ROUGHNESS) return encodedAs(vec3(m.roughness));
    if (which == VIEW_OCCLUSION) return encodedAs(vec3(m.occlusion));
    if (which == VIEW_EMISSIVE) return encodedAs(m.emissive);
    if (which == VIEW_F0) return encodedAs(mix(m.F0, m.baseColor, m.metallic));
    // sample 10's layers, on a material without them: no coat (its normal the surface's), sheen
    // or transmission; the base keeps all under no sheen, and nothing is lost in no volume
    if (which == VIEW_CLEARCOAT_NORMAL) return encodedAs(0.5 + 0.5 * m.N);
    if (which == VIEW_SHEEN_SCALING || which == VIEW_VOLUME_ATTENUATION) return vec3(1.0);
    if (which >= VIEW_CLEARCOAT) return vec3(0.0);
    // KHR_materials_unlit: no light takes part in the picture (the base colour is it), so every
    // term of the lighting is 0 there.
    if (unlit) return vec3(0.0);

    float D = 0.0, G = 0.0, NdotL = 0.0, Vis = 0.0;
    vec3 F = vec3(0.0), specular = vec3(0.0), diffuse = vec3(0.0), direct = vec3(0.0);
    for (int i = 0; usePunctual && i < punctualLightCount; ++i)
    {
        vec3 L;
        vec3 radiance = punctualRadiance(i, WorldPos, L);
        direct += gltfDirectLight(m.N, V, L, radiance, m.diffuseColor, m.F0, m.baseColor,
                                  m.metallic, m.roughness);
        if (dot(m.N, L) <= 0.0 || radiance == vec3(0.0))
            continue;
        GltfBrdf b = gltfBrdf(m.N, V, L, m.diffuseColor, m.F0, m.baseColor, m.metallic,
                              m.roughness);
        D += b.D;
        G += b.Vis * 4.0 * b.NdotL * b.NdotV;
        Vis += b.Vis;
        F += b.F;
        specular += b.specular;
        diffuse += b.diffuse;
        NdotL += b.NdotL;
    }
    if (which == VIEW_D) return encodedAs(viewCompress(vec3(D)));
    if (which == VIEW_G) return encodedAs(viewCompress(vec3(G)));
    if (which == VIEW_VISIBILITY) return encodedAs(viewCompress(vec3(Vis)));
    if (which == VIEW_F) return encodedAs(viewCompress(F));
    if (which == VIEW_SPECULAR) return encodedAs(viewCompress(specular));
    if (which == VIEW_DIFFUSE) return encodedAs(viewCompress(diffuse));
    if (which == VIEW_NDOTL) return encodedAs(viewCompress(vec3(NdotL)));
    if (which == VIEW_DIRECT) return toneMap(direct, toneMapper, exposure);

    GltfAmbientTerms t =
        gltfAmbientTerms(m.N, V, m.diffuseColor, m.F0, m.baseColor, m.roughness);
    float shown = useIbl ? m.occlusion : 0.0;
    vec3 ambientDiffuse = (1.0 - m.metallic) * t.diffuse * shown;
    vec3 ambientSpecular = mix(t.dielectricSpecular, t.metal, m.metallic) * shown;
    vec3 ambient = useIbl ? ambientLightGltf(m.N, V, m.diffuseColor, m.F0, m.baseColor,
                                             m.metallic, m.roughness) * m.occlusion
                          : vec3(0.0);
    if (which == VIEW_AMBIENT) return toneMap(ambient, toneMapper, exposure);
    if (which == VIEW_MULTIPLE_SCATTERING)
        return encodedAs(viewCompress(mix(t.dielectricMultiple, t.metalMultiple, m.metallic) * shown));
    return encodedAs(iblView(which, t.reads.irradiance, t.reads.prefilteredColor,
                             t.reads.envBRDF, ambientDiffuse, ambientSpecular, vec3(0.0),
                             vec3(1.0, 0.0, 1.0)));
}
#endif  // TERM_VIEWS
