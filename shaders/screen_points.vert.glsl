#version 450 core
// Squares of kScreenTile pixels drawn as points (prototype).
layout(location = 0) in vec2 a_pixel;  // the square's centre, in pixels from the target's lower left
uniform vec2 u_target_size;
void main() {
  gl_Position = vec4(a_pixel / u_target_size * 2.0 - 1.0, 0.0, 1.0);
}
