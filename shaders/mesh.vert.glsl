#version 450 core
// Shared by the light-depth, geometry and floor passes: transforms the normalized mesh.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;

out vec3 v_object_pos;
out vec3 v_object_normal;
out vec3 v_world_pos;
out vec3 v_world_normal;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_object_pos = a_position;
  v_object_normal = a_normal;
  v_world_pos = world.xyz;
  v_world_normal = u_normal_matrix * a_normal;
  gl_Position = u_view_proj * world;
}
