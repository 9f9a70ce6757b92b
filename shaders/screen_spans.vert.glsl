#version 450 core
// Rectangles given in pixels (two triangles each, from a vertex buffer): a pass that draws only
// those parts of the target (FXAA over the tiles the mesh can cover, render/screen_tiles.h).
layout(location = 0) in vec2 a_pixel;  // a corner, in pixels from the target's lower left
uniform vec2 u_target_size;
void main() { gl_Position = vec4(a_pixel / u_target_size * 2.0 - 1.0, 0.0, 1.0); }
