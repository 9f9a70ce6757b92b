#version 450 core
// One triangle that covers the screen; no vertex buffer needed. It lies on the far plane
// (depth 1, what the G-buffer's background holds), so a pass with the G-buffer's depth attached
// and the depth test GL_GREATER shades only the surface (gl::setSurfaceOnlyScreenPassState).
out vec2 v_uv;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
