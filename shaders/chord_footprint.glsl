// The transmission's chord at a part's rim: where the light's map is read for it, and the walk's
// footprint of entries around a short chord (the `marble` mode's lighting pass, transmission_thickness).
// Needs from the includer: transmission_chord.glsl (u_chord_decay), light_vector,
// u_light_view_proj, u_light_texel_world (deferred_common.glsl), u_light_distance, u_light_near_far.
//
// Why (docs/quality.md, "Twenty-ninth session: teapot-back's rim right of the knob's shadow" and
// "Thirtieth session: the rim's chord read at the exit's own light ray"): the chord is read at the
// inward-offset exit P_in = P - 2 texels N (against acne), and on a face turned from the light
// (N.L < 0) that offset has a part across the light, 2 texels sqrt(1 - (N.L)^2), up to two texels
// sideways in the light's map. At teapot-back's lid rim (N.L -0.3 ... -0.7) the step crosses the
// knob's shadow edge and another part's: the read finds chords of 8-34 mm where the ray-cast chord
// from P is 1.3-2.5 mm, and the lit band starts 2-3 pixels late. Reading at P's own light ray
// (the offset's part along the light kept) puts the band's start where Cycles' is, but the straight
// short chord is then 1.3-1.45x Cycles' band: the walk's light at P comes from entries around P's
// own, within about 2 mm (the walk's 3/4 radius, walkRingRadiusMm), and beside a shadow edge some
// of them are in the shadow. So below a short chord half the light is the straight chord's and
// half the mean over a ring of the light map's texels at the walk's radius, each tap's own chord
// (as s29-teapot's lit_face_spread splits the walk: the inner half at the entry, the outer half at
// its median radius). Both only where P_in's read finds the longer chord (chord_own_ray_share):
// elsewhere P_in's read as before, which the gather's slanted slab, shell and sheet tests hold to.
// Ten reference scenes against main: teapot-back +0.0034 SSIM, the mean +0.0003, buddha-side -0.0006
// the largest fall. Cost (docs/performance.md, same title): +7.8 M instructions of the dragon's
// 800^2 camera frame (a second transmission_chord read and the ring; llvmpipe runs both ways of the
// branch). Known leftover: where the lid's open gap lets the light ray from a face turned away pass
// no stone (teapot-back rows 83-84, x 122-123), the map's texel is the face itself, seen from behind
// (a mesh with holes draws both faces into the map), and its chord is a fraction of a mm: a faint
// spot 0.025 against Cycles' 0.010 (Cycles has the spot too; SSIM there above main's).

#ifndef CHORD_FOOTPRINT_GLSL
#define CHORD_FOOTPRINT_GLSL

// Where the chord's texels are read for the exit P on its own light ray (L toward the light, NoL =
// N.L < 0: a face turned from the light), at P_in's distance from the light: P - 2 texels (N.L) L,
// the inward offset's part along the light only.
vec3 chord_read_point(vec3 P, vec3 L, float NoL) {
  return P - (2.0 * u_light_texel_world * NoL) * L;
}

// How much of the exit's own ray's read (chord s_at) replaces P_in's (s_in). Where the entry is the
// exit face's parallel (a slab, a sheet, a shell, a body's far side: what the gather and the tests
// TransmissionSlab, TransmissionShell, TransmissionSheet model) P_in's ray finds the shorter chord,
// (T - 2 texels) / c against T / c - 2 texels c (c = -N.L, T the thickness along the normal), and
// P_in's read is kept as it was. Only where P_in's read finds the longer chord has its sideways step
// crossed onto a surface nearer the light (a shadow's caster: teapot-back's knob beside its lid rim),
// and there the exit's own ray's read is taken, over one texel of disagreement.
float chord_own_ray_share(float s_in, float s_at) {
  return smoothstep(0.0, u_light_texel_world, s_in - s_at);
}

// The short chord's footprint: below `from` of chord (scene units; blended out by 2 from, as the
// gather, gathered_transport, blends in: the two share the range) the chord s read at `at` becomes
// the chord of T = 1/2 exp(-sigma s) + 1/2 mean_i exp(-sigma s_i), s_i the chords at CHORD_FOOTPRINT_TAPS
// taps `ring` (scene units: the walk's 3/4 radius, walkRingRadiusMm, 2.06 mm in the issue's stone)
// from `at` across the light, +-e1 (L x up: level) and +-e2 (L x e1), each one nearest texel of
// the light's map against d, the exit's distance from the light (P_in's for every tap: a tap's own
// exit lies across the light from `at`, ring^2 / 2d farther, 0.007 mm for 2 mm at the reference
// scenes' 3 units; exactly d for a directional light). A tap counts, the weights normalized, where
// its texel saw stone; one off the map or whose texel saw nothing is left out (no surface for the
// light to enter by). A tap whose entry lies at or beyond the exit's distance counts as a zero
// chord: lit stone beside the exit (at a rim lit at grazing light, its lit top beside the band),
// whose distance across the light the ring stands for. Where none counts, s itself.
// Measured on teapot-back (docs/quality.md, "Thirtieth session: the rim's chord read at the exit's
// own light ray"), the taps along the light map's axes: such taps left out, as transmission_chord
// leaves out its own texels at or behind p, SSIM 0.9517; counted at |d - entry| along the light,
// as the gather counts its taps, 0.9530; as zero chords 0.9537 (main 0.9500). Across the light
// (e1, e2) rather than along the map's axes: buddha-side -0.0009 instead of -0.0011 against main.
// Approximations: the walk's outer half on one ring of four taps at one radius (the three channels'
// luminance-weighted mean), its inner half at the read's own chord, the transport exp(-sigma s)
// (transmission_chord's decay: the walk's -d ln T / ds 0.23-0.31 per mm from 3 mm of chord on,
// steeper below, where the blend takes it), a tap's chord from one nearest texel (0.1-0.3 mm
// texels, under a sixth of the ring). Nothing fitted: the ring is the walk's, the range the gather's.
const int CHORD_FOOTPRINT_TAPS = 4;
float chord_footprint(vec3 at, float d, float s, float ring, float from) {
  float blend = 1.0 - smoothstep(from, 2.0 * from, s);
  if (blend <= 0.0 || s <= 0.0) return s;
  vec4 clip = u_light_view_proj * vec4(at, 1.0);
  vec3 L = light_vector(at);
  vec3 e1 = normalize(cross(L, abs(L.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0))) * ring;
  vec4 c1 = u_light_view_proj * vec4(e1, 0.0), c2 = u_light_view_proj * vec4(cross(L, e1), 0.0);
  float octaves = u_chord_decay * 1.442695;  // exp2 and log2, as transmission_chord
  vec2 sum = vec2(0.0);  // (light through, weight)
  for (int i = 0; i < CHORD_FOOTPRINT_TAPS; ++i) {
    vec4 c = clip + (i == 0 ? c1 : i == 1 ? -c1 : i == 2 ? c2 : -c2);
    vec2 tap = c.xy / c.w * 0.5 + 0.5;
    float entry = textureLod(u_light_distance, tap, 0.0).r;  // GL_NEAREST
    float s_i = d - entry;
    bool counts = all(lessThan(abs(tap - 0.5), vec2(0.5))) && entry < u_light_near_far.y + 1.0;
    sum += counts ? vec2(exp2(-octaves * max(s_i, 0.0)), 1.0) : vec2(0.0);
  }
  if (sum.y <= 0.0) return s;
  float through = 0.5 * exp2(-octaves * s) + 0.5 * sum.x / sum.y;
  return mix(s, -log2(through) / octaves, blend);
}
#endif
