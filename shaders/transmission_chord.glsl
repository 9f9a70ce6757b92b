// The transmission's chord read from the light's distance map: the four texels around a point,
// and the chord the light crossed to reach it (the `marble` mode's lighting pass).
// Needs from the includer: deferred_common.glsl (u_light_view_proj, u_light_texel_world,
// light_distance_of), u_light_distance and u_light_near_far (lighting.frag.glsl).

// Attenuation of the diffuse light per scene unit, sqrt(3 sigma_a sigma_t) averaged over the
// channels (marble::diffusionAttenuationMm x mm per unit, lighting_pass.cpp).
uniform float u_chord_decay;

// The light map's four texels around p, as textureGather returns them (.x .y .z .w): where the
// light entered (entered) and at what cosine (cosines); the result, their bilinear weights, 0 for a
// texel that saw nothing (its "nothing hit" distance would invent a huge entry) and all 0 off the map.
vec4 light_texels_at(vec3 p, out vec4 entered, out vec4 cosines) {
  entered = vec4(0.0);
  cosines = vec4(0.0);
  vec4 clip = u_light_view_proj * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return vec4(0.0);
  vec2 size = vec2(textureSize(u_light_distance, 0));
  vec2 t = (ndc.xy * 0.5 + 0.5) * size - 0.5;
  vec2 base = floor(t);
  vec2 f = t - base;
  entered = textureGather(u_light_distance, (base + 1.0) / size, 0);
  cosines = textureGather(u_light_distance, (base + 1.0) / size, 1);
  vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  return w * vec4(lessThan(entered, vec4(u_light_near_far.y + 1.0)));
}

// The chord the light crossed before reaching p (.x, scene units) and the cosine it entered at
// (.y), for the transmission (lighting.frag.glsl, transmission_thickness).
//
// Each texel gives its own chord s_i = d(p) - entry_i. Where the four texels lie on one surface
// they differ by a texel times the surface's slope, and the bilinear mean of the entries is the
// chord. Across an edge of the light's map (a part's silhouette seen from the light: the teapot's
// lid rim below the dome and the knob, where the inward offset moves the read up to two texels
// across the lip's outline) they lie on two surfaces 20-45 mm apart, and the mean of the entries
// is an entry on neither: a chord of 6.8-45 mm where the ray-cast one is 0.5-2.5 mm
// (docs/quality.md, "Twenty-sixth session: teapot-back's loss by region"), whose transport is nil.
// What the footprint receives is the bilinear mean of the light each texel lets through, as a
// shadow map's percentage-closer filter averages the test, not the depth (Reeves et al. 1987).
// The transport falls off as exp(-sigma_tr s) once the chord is a few mm long (the walk's table:
// -d ln T / ds of the green channel 0.23-0.31 per mm at 3-15 mm; sigma_tr 0.11 / 0.19 / 0.32 per mm
// for principled-white, their mean 0.21), so the chord returned is the one whose exp(-sigma_tr s)
// is that mean: s = s_min - ln(sum w_i exp(-sigma_tr (s_i - s_min)) / sum w_i) / sigma_tr, and the
// cosine is the texels' cosines weighted by the light each lets through. On one surface this is
// the bilinear chord less sigma_tr var(s_i) / 2, under a micrometre for the map's 0.1-0.2 mm
// texels; across the edge the texels on the near surface carry the light. Ten scenes against
// main (docs/quality.md, "Twenty-seventh session: the chord's read across the light map's edge"):
// teapot-back +0.0024 SSIM, the mean +0.0002, no scene down by more than 0.0002; the decay
// measured 0.1-0.3 per mm, within 0.0002 everywhere except teapot-back (+0.0010 at 0.1 per mm).
// A texel whose chord is under half a texel (an entry at or behind p: the map saw p's own side,
// an open wall or a grazing face, s26-teapot2) tells nothing of the light reaching p and is left
// out, as a texel that saw nothing is; where all four are such, the bilinear read as before (its
// zero chord takes the exit's own cosine, entry_cosine in lighting.frag.glsl).
// The texels are read around `at`, the chords taken from p's distance to the light: at = p, or p
// moved across the light (chord_footprint.glsl, chord_read_point: the exit's own light ray).
vec2 transmission_chord(vec3 p, vec3 at) {
  vec4 entered, cosines;
  vec4 w = light_texels_at(at, entered, cosines);
  float weight = w.x + w.y + w.z + w.w;
  if (weight <= 0.0) return vec2(0.0);
  float d = light_distance_of(p);
  vec4 s = max(vec4(d) - entered, vec4(0.0));
  vec4 keep = w * smoothstep(vec4(0.0), vec4(0.5 * u_light_texel_world), s);
  float kept = keep.x + keep.y + keep.z + keep.w;
  if (kept <= 0.0) return vec2(max(d - dot(w, entered) / weight, 0.0), dot(w, cosines) / weight);
  vec4 s_kept = mix(vec4(3.0e38), s, greaterThan(keep, vec4(0.0)));
  float s_min = min(min(s_kept.x, s_kept.y), min(s_kept.z, s_kept.w));
  // exp and log in base 2 (what llvmpipe computes them by): the decay in octaves per unit.
  float octaves = u_chord_decay * 1.442695;
  vec4 through = keep * exp2(-octaves * max(s - vec4(s_min), vec4(0.0)));
  float total = through.x + through.y + through.z + through.w;
  return vec2(s_min - log2(total / kept) / octaves, dot(through, cosines) / total);
}
