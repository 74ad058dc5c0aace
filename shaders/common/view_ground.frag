#version 330 core
// What a term view is drawn on (App::clearFrame): a checker of two greys in 16-pixel cells, not
// the sky or the scene, so that no value of a view melts into it (a flat value differs from one
// of the two greys by 32 levels at least).
out vec4 FragColor;

uniform vec3 dark;   // written as they are: the App picks them for the target's encoding
uniform vec3 light;

void main()
{
    vec2 cell = floor(gl_FragCoord.xy / 16.0);
    FragColor = vec4(mod(cell.x + cell.y, 2.0) < 1.0 ? dark : light, 1.0);
}
