// The first bounce that enters the stone on its lit side (bounce_entry.frag.glsl, gathered on a
// level of the reflective shadow map's grid), read for the transmission in the lighting pass: light one
// lit part sends to another lit part, entering there beside the light's own and crossing a thin
// part to the side the camera sees (lighting.frag.glsl, marble_entering).
// Needs from the includer: deferred_common.glsl (u_light_view_proj).
layout(binding = UNIT_LIGHTING_BOUNCE_ENTRY) uniform sampler2D u_bounce_entry;

// Irradiance / PI per unit of the light's radiance that the first bounce brings to where the
// light's ray through p entered the stone, the emitters' albedo and Fresnel factors applied (by
// bounce_entry.frag.glsl, as bounce_merge.frag.glsl applies them). Bilinear in the grid: the four
// turns of the gather's pattern are averaged (the turn's luck moves the back-lit scenes by at most
// 0.0002 of SSIM: not evened out as the camera-side grids are, docs/quality.md, "Twenty-first
// session: the further bounces' pattern evened out"), and the texels that saw nothing (0) fade the
// value at the light's silhouette over a texel.
vec3 bounce_entering_at(vec3 p) {
  vec4 clip = u_light_view_proj * vec4(p, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec3(0.0);
  return texture(u_bounce_entry, uv).rgb;
}
