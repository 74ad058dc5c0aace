#version 330 core
// The browser's way to show an sRGB render target (common/gl/framebuffer.cpp): WebGL 2 decodes an
// sRGB source into the canvas's linear buffer when it blits (OpenGL ES 3.0, 4.3.3), which showed
// the glTF pages' pictures decoded twice, too dark. So the picture is drawn instead: sampled
// (decoded to linear, exactly), then encoded again by the sRGB curve (IEC 61966-2-1), which gives
// every byte back (the canvas against the page's own file: tests/web).
in vec2 TexCoords;
out vec4 FragColor;

uniform sampler2D picture;

void main()
{
    vec3 linear = texture(picture, TexCoords).rgb;
    vec3 encoded = mix(linear * 12.92, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055,
                       step(vec3(0.0031308), linear));
    FragColor = vec4(encoded, 1.0);
}
