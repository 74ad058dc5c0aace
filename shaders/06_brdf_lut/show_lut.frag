#version 330 core
// One panel of the BRDF LUT: its R and G channels (scale and bias to F0) as red and green, the
// picture both texts show, or its B channel (the Charlie sheen albedo, 0 to about 1.09) as grey.
// NdotV grows to the right, roughness upwards: the LUT's own axes, texel (i, j) at
// ((i + 0.5) / N, (j + 0.5) / N).
out vec4 FragColor;
in vec2 TexCoords;

uniform sampler2D brdfLUT;
uniform bool showSheen;

void main()
{
    vec3 lut = texture(brdfLUT, TexCoords).rgb;
    vec3 color = showSheen ? vec3(lut.b) : vec3(lut.rg, 0.0);
    FragColor = vec4(color, 1.0);  // no tone mapping or sRGB curve: the values, as the texts show them
}
