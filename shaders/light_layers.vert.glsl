#version 450 core
// The light's entry and exit layers' vertex stage (LightDepthPass's third draw): mesh.vert.glsl's
// transform with only the two outputs light_layers.frag.glsl reads. On llvmpipe a draw of the
// mesh costs mostly its vertices and their outputs' setup (the layers' draw at 128² cost the
// dragon's light frame 35 M instructions, at 256² 43 M: docs/performance.md, "Twenty-second
// session: the hidden mirror image").
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;

out vec3 v_world_pos;
out vec3 v_world_normal;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world_pos = world.xyz;
  v_world_normal = u_normal_matrix * a_normal;
  gl_Position = u_view_proj * world;
}
