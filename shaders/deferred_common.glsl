// What the deferred screen passes (lighting.frag.glsl, post.frag.glsl) share: the camera, to
// rebuild a surface point from the depth buffer, and the light. Set by
// marble::setFrameUniforms (src/marble/render/frame_uniforms.h).
uniform mat4 u_inv_view_proj;
uniform mat4 u_view_proj;  // world to the camera's clip space (the inverse of the above)
uniform vec4 u_view_depth_row;  // u_view_proj's last row: dot(it, (X, 1)) is X's clip w, its view depth
uniform vec3 u_camera_pos;
uniform mat4 u_light_view_proj;
#include "light_geometry.glsl"
uniform vec3 u_light_radiance;      // colour x intensity
uniform float u_light_texel_world;  // world size of one light-map texel at the object
uniform float u_light_ref_distance; // d0: the point light's distance to the scene centre

// World-space point of the surface seen at uv with depth-buffer value `depth`.
vec3 surface_point(vec2 uv, float depth) {
  vec4 world = u_inv_view_proj * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
  return world.xyz / world.w;
}

// The `marble` mode's irradiance at normal incidence, at distance d from the light (needs PI).
// Intensity I gives PI * I at d0 (so a white Lambertian surface facing the light there
// reflects I, as in the paper's modes, and a scene keeps its exposure); a point light falls
// off by the inverse-square law around it, E = PI I (d0 / d)^2, exactly as Cycles' point light
// of power 4 PI^2 d0^2 I does (tools/cycles_reference.py). A directional light has no falloff.
// light_falloff: the same per unit of u_light_radiance (the bounce gathers scalars and colours
// them once, bounce_upsample.glsl).
float light_falloff(float d) {
  if (u_light_directional == 1) return PI;
  float r = u_light_ref_distance / max(d, 1e-4);
  return PI * r * r;
}
vec3 light_irradiance(float d) { return u_light_radiance * light_falloff(d); }
