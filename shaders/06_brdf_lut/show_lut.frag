#version 330 core
// One panel of the BRDF LUT: its R and G channels (scale and bias to F0) as red and green, the
// picture both texts show, or its B channel (Charlie sheen, at most about 0.1) as grey, times
// sheenScale so that its shape shows. NdotV grows to the right,
// roughness upwards: the LUT's own axes, texel (i, j) at ((i + 0.5) / N, (j + 0.5) / N).
out vec4 FragColor;
in vec2 TexCoords;

uniform sampler2D brdfLUT;
uniform bool showSheen;
uniform float sheenScale;

void main()
{
    vec3 lut = texture(brdfLUT, TexCoords).rgb;
    vec3 color = showSheen ? vec3(lut.b * sheenScale) : vec3(lut.rg, 0.0);
    FragColor = vec4(color, 1.0);  // no tone mapping or sRGB curve: the values, as the texts show them
}
