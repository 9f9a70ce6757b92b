// Whether the light reaching a point of the transmission's gather crossed air after a first part of
// the stone: the point lies beyond that part's exit along its light ray (the light's entry and exit
// layers, light_layers.frag.glsl). Read by the gather's taps, its centre disc and the straight
// model (lighting.frag.glsl), which then count no light from that entry.
//
// Why nothing: the references' Cycles (3.4.1) carries no light through a second piece of stone
// behind air. Its random walk ends where it meets the surface; the light then leaves the first part
// and reaches the second by a diffuse bounce, after which the Principled BSDF's subsurface weight is
// 0 (svm/closure.h, PATH_RAY_DIFFUSE_ANCESTOR): the second piece is opaque to it. Measured
// (docs/quality.md, "Twenty-ninth session: ... the air between two parts"): two plates 1.8 mm and
// 9.6 mm thick with 4.8 mm of air between, lit from straight behind, at 128 samples: Cycles 0 in
// every pixel; the one 16.2 mm plate of the same chord 0.024 / 0.0061 / 0.0012, marble before this
// 0.028 / 0.0057 / 0.0010 for both (its chord from the light's map counts the air as stone). The
// light that enters the second piece directly, beside the first part's shadow, is the gather's taps
// there, whose own light ray meets the second piece first: they keep it.
//
// Approximations, each stated:
// - the way is tested at one point, AIR_GAP_AT of the way from the exit to the entry (the middle):
//   a gap nearer either end than that is stepped over. Not the tap's own point in the light's plane
//   through the exit: that plane leaves a slanted slab on one side although each entry's way stays
//   in it (TransmissionSlab's 4 mm slab at 45 degrees read 0.86-0.90 of its law with it). Measured
//   on the ten reference scenes (mean / buddha-back / dragon-back against main): the middle
//   -0.00005 / +0.0020 / -0.0017; a quarter of the way from the exit -0.00002 / +0.0026 / -0.0023;
//   the exit itself (every tap) -0.00004 / +0.0037 / -0.0030. Where it cuts (the gated pixels of
//   the back-lit scenes) T / Cycles' walk light Cd goes from 1.23 / 1.65 / 1.32 (dragon-, buddha-,
//   teapot-back) to 0.92 / 1.09 / 0.99: the losses are marble's indirect light there (0.55-0.73 of
//   Cycles'), which the light through the air stood in for;
// - the layers hold the first part along each light ray only (a third piece behind a second is not
//   told apart from the second) and are read at the nearest texel of a quarter-size map: a point in
//   its own part lies within the read's error of that part's exit, most at grazing exits (the exit
//   surface moves by a texel times its slope across one read). The ramp starts AIR_GAP_FROM layer
//   texels beyond the exit and is full at AIR_GAP_FULL; measured with the light-plane point at 1-3,
//   2-6 and 3-9 texels (dragon-back -0.0035 / -0.0004 / +0.0003): the widest kept, a tolerance
//   chosen on the scenes, not derived;
// - off the layers' map, or where the texel holds no part (LightDepthPass::kNoLayer), no air.
// Needs from the includer: deferred_common.glsl (light_distance_of, u_light_view_proj,
// u_light_texel_world) and u_light_distance (the light's map, whose texel the layers' is scaled from).

layout(binding = UNIT_LIGHTING_LIGHT_LAYERS) uniform sampler2D u_light_layers;  // entry, exit

const float AIR_GAP_FROM = 3.0;  // layer texels beyond the first part's exit
const float AIR_GAP_FULL = 9.0;
const float AIR_GAP_AT = 0.5;   // the point of the way tested, from the exit (0) to the entry (1)

// 0 where q lies in or before the first part its light ray meets, 1 where it lies beyond that part's
// exit (in the air behind it, or in a second piece), a ramp between.
float beyond_first_part(vec3 q) {
  vec4 clip = u_light_view_proj * vec4(q, 1.0);
  if (clip.w <= 0.0) return 0.0;
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return 0.0;
  vec2 layers = textureLod(u_light_layers, uv, 0.0).xy;  // the texel ivec2(uv x size): GL_NEAREST (nearest_texel.glsl)
  if (!(layers.x < layers.y)) return 0.0;                // LightDepthPass::kNoLayer in either: no part
  float texel = u_light_texel_world * float(textureSize(u_light_distance, 0).x) / float(textureSize(u_light_layers, 0).x);
  return smoothstep(AIR_GAP_FROM * texel, AIR_GAP_FULL * texel, light_distance_of(q) - layers.y);
}

// The light entering at the map's entry above q (its chord sk: the entry lies sk toward the light
// from q) and leaving at P_in: whether its way crossed air behind a first part, tested at the point
// AIR_GAP_AT of the way from P_in to the entry (one point; a part thinner than the test's reach is
// stepped over). Not q itself: the gather's taps lie in the light's plane through P_in, which leaves
// a slanted slab on one side although the way from each entry to P_in stays in it.
float air_on_way(vec3 P_in, vec3 q, float sk) {
  vec3 entry = q + light_vector(q) * sk;
  return beyond_first_part(mix(P_in, entry, AIR_GAP_AT));
}
