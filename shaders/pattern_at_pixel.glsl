// The marble pattern's colour at a pixel of the G-buffer (paper §3.1, §4): the object-space
// point and normal rebuilt from the depth and the world normal, then marble_albedo. Used by
// the albedo pass and by the post pass, which evaluates the pattern itself in `marble` frames
// whose albedo changed (one pass fewer, and the G-buffer read once). Needs marble_pattern.glsl.
// Set by marble::setPatternViewUniforms (src/marble/render/albedo_pass.h).
uniform mat4 u_inv_model_view_proj;      // clip space -> the mesh's object space
uniform mat3 u_world_to_object_normal;   // transpose of the model matrix's 3x3
// Veins seen through the polish (`marble` mode's post pass; 0 elsewhere: the surface only):
// the diffusion attenuation sigma_tr per object unit and 1 / ior (marble::seenVeinAttenuation).
uniform float u_pat_seen_sigma_tr;
uniform float u_pat_seen_eta;

// uv: the pixel's centre in [0,1]^2; z: its depth-buffer value (< 1); worldNormal: unit.
vec3 albedo_at_pixel(vec2 uv, float z, vec3 worldNormal) {
  vec4 p = u_inv_model_view_proj * vec4(vec3(uv, z) * 2.0 - 1.0, 1.0);
  vec3 objectNormal = normalize(u_world_to_object_normal * worldNormal);
  vec3 objectPos = p.xyz / p.w;
  // The view ray through this pixel (the near plane's point to the surface's), refracted in.
  // (No branch on u_pat_seen_sigma_tr: llvmpipe runs both sides of it, i.e. the pattern twice;
  // at 0 the seen albedo is the surface's, pattern_core.glsl pat_cells_cover.)
  vec4 nearPoint = u_inv_model_view_proj * vec4(uv * 2.0 - 1.0, -1.0, 1.0);
  vec3 view = normalize(objectPos - nearPoint.xyz / nearPoint.w);
  vec3 N = dot(view, objectNormal) > 0.0 ? -objectNormal : objectNormal;
  vec3 ray = refract(view, N, u_pat_seen_eta);
  float cosT = max(-dot(ray, N), 0.05);
  return marble_albedo_seen(objectPos, objectNormal, ray, u_pat_seen_sigma_tr * cosT);
}
