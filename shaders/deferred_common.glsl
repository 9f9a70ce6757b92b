// What the deferred screen passes (lighting.frag.glsl, post.frag.glsl) share: the camera, to
// rebuild a surface point from the depth buffer, and the light. Set by
// marble::setFrameUniforms (src/marble/render/frame_uniforms.h).
uniform mat4 u_inv_view_proj;
uniform vec3 u_camera_pos;
uniform mat4 u_light_view_proj;
uniform vec3 u_light_pos;
uniform vec3 u_light_dir;
uniform int u_light_directional;
uniform vec3 u_light_radiance;      // colour x intensity
uniform float u_light_texel_world;  // world size of one light-map texel at the object

// World-space point of the surface seen at uv with depth-buffer value `depth`.
vec3 surface_point(vec2 uv, float depth) {
  vec4 world = u_inv_view_proj * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
  return world.xyz / world.w;
}

// Unit vector from P toward the light.
vec3 light_vector(vec3 P) {
  return u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - P);
}
