// The marble pattern's colour at a pixel of the G-buffer (paper §3.1, §4): the object-space
// point and normal rebuilt from the depth and the world normal, then marble_albedo. Used by
// the albedo pass and by the post pass, which evaluates the pattern itself in `marble` frames
// whose albedo changed (one pass fewer, and the G-buffer read once). Needs marble_pattern.glsl.
// Set by marble::setPatternViewUniforms (src/marble/render/albedo_pass.h).
uniform mat4 u_inv_model_view_proj;      // clip space -> the mesh's object space
uniform mat3 u_world_to_object_normal;   // transpose of the model matrix's 3x3

// uv: the pixel's centre in [0,1]^2; z: its depth-buffer value (< 1); worldNormal: unit.
vec3 albedo_at_pixel(vec2 uv, float z, vec3 worldNormal) {
  vec4 p = u_inv_model_view_proj * vec4(vec3(uv, z) * 2.0 - 1.0, 1.0);
  vec3 objectNormal = normalize(u_world_to_object_normal * worldNormal);
  return marble_albedo(p.xyz / p.w, objectNormal);
}
