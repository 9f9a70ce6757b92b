// The bounce's visibility through the stone of the first part the light meets (session 23; the
// through-stone test is session 22's s22-cross, after session 19's bounce_crosses_stone, commit
// 435f961): a receiver takes no bounce whose way from the emitter passes through that part's stone,
// if it lies behind that part (in its shadow: a fold of the robe behind the raised arm, the body
// behind a fold; since session 23) or on a part thick along the light (since session 28: the exit
// face of the back-lit buddha's body, lit through the body by the emitters on its far side).
// Tested at BOUNCE_STONE_POINTS points of the segment against the light's entry and exit layers
// (light_layers.frag.glsl: a point whose light distance lies between the texel's entry and exit is
// in that part's stone; beyond the exit it is in the air behind the part, before the entry in the
// air in front of it).
// Why not every receiver: light from a lit surface that reaches another through the stone is that
// part's transmission (its glow, lighting.frag.glsl), which the reflective shadow map does not hold
// as an emitter. Behind a part the light leaves that part through its exit face first; for a thick
// part it is nothing (T(20 mm) / R_inf = 0.006, session 10's slab fit). A receiver on a thin part
// (its own exit side) keeps the light through its own stone: there it stood in for the part's own
// glow, which marble's transmission left short on the back-lit dragon's thin coils (s22-cross,
// testing every receiver, cost dragon-back 0.016 on session 22's main, session 23's gate 0.0019;
// docs/quality.md, "Twenty-third session: the bounce through another part's stone, for receivers
// in that part's light shadow"). On session 27's main, testing every receiver costs dragon-back
// only 0.0002; the gate at BOUNCE_THICK_PART keeps it whole (docs/quality.md, "Twenty-eighth
// session: the first bounce through the back-lit body").
// Cost: on llvmpipe the gate saves nothing (a draw's lanes take both ways), so every receiver pays
// the per-sample test: +12.5 M instructions of the dragon's 800² camera frame (docs/performance.md).
// Approximations, each stated:
// - "behind" is more than BOUNCE_BEHIND_TEXELS layer texels beyond the exit of the first part at
//   the receiver's own texel (nearest read); a receiver on that part's exit face is on it, not
//   behind it. Measured 2, 6, 15: 2 the best for buddha-side, 15 loses most of it;
// - "thick" is the first part's chord along the light at the receiver's own texel (exit less
//   entry) over BOUNCE_THICK_PART world units: 20 mm at the reference scenes' 100 mm a unit, where
//   the slab passes 0.6 % of what it reflects. Measured on the ten reference scenes (session 28):
//   every receiver tested (no gate), 0.1, 0.2 and 0.3 units within 0.00006 of each other in the
//   mean (+0.00023 to +0.00029), buddha-back +0.0020 to +0.0021 with each; 0.1 and 0.2 leave
//   dragon-back as it was (no gate: -0.0002), 0.4 loses buddha-back's gain (its chest is thinner);
//   0.2 kept for the slab's 20 mm. The gather reads no material parameter, so the gate is in world units:
//   at other scales (mm per unit) it holds the reference scenes' thickness, not the slab's law;
// - BOUNCE_STONE_POINTS points evenly spaced strictly inside the segment: a part thinner than the
//   spacing between two points is stepped over (5 points measured no better than 3; the midpoint
//   alone keeps half buddha-side's gain and all of dragon-back, for the same mean: kept);
// - the layers hold the first part along each light ray only: a second part behind it is not
//   stone to this test, nor is the air between two parts (the shade between dragon-side's coils
//   keeps its bounce, which a test against the light's one depth map removed: s22-side, -0.05);
// - a point counts as stone only more than a layer texel inside (the layers' nearest read and the
//   surfaces' slope within a texel: the segment's ends lie on the surface); off the map, or where
//   no exit lies behind the entry (LightDepthPass::kNoLayer), it is air.
// Needs from the includer: deferred_common.glsl (light_distance_of, u_light_view_proj),
// u_light_layer_texel_world (BouncePass: a texel of the layers at the object).

#include "nearest_texel.glsl"

layout(binding = UNIT_LIGHTING_LIGHT_LAYERS) uniform sampler2D u_bounce_layers;  // entry, exit
uniform float u_light_layer_texel_world;

const int BOUNCE_STONE_POINTS = 1;  // the midpoint: the lead chose it at the merge (same mean as 3, no scene down)
const float BOUNCE_BEHIND_TEXELS = 2.0;
const float BOUNCE_THICK_PART = 0.2;  // world units of the first part's chord along the light

// What the test needs of the receiver, computed once per gather (bounce_gather): whether its ways
// are tested (it lies behind the first part, or on a thick one), and its light-clip position, which the way's points interpolate (clip
// coordinates are linear in the position: one projection per sample, the emitter's).
struct BounceStoneReceiver {
  bool tested;
  vec4 clip;  // u_light_view_proj * P
};

// The layers' texel under a light-clip position (-1 off the map).
ivec2 bounce_layers_texel(vec4 clip) {
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return ivec2(-1);
  return ivec2(uv * vec2(textureSize(u_bounce_layers, 0)));
}

// P behind the first part the light meets along its ray, or that part thick along it (layers.y
// 1e30: LightDepthPass::kNoLayer, no exit: no part)?
BounceStoneReceiver bounce_stone_receiver(vec3 P, vec4 clipP) {
  ivec2 t = bounce_layers_texel(clipP);
  vec2 layers = t.x < 0 ? vec2(1e30) : nearest_texel(u_bounce_layers, t).xy;  // entry, exit
  bool behind = light_distance_of(P) > layers.y + BOUNCE_BEHIND_TEXELS * u_light_layer_texel_world;
  return BounceStoneReceiver(layers.y < 1e20 && (behind || layers.y - layers.x > BOUNCE_THICK_PART), clipP);
}

// True where a point of the segment from the receiver P to the emitter xp lies in the stone of the
// first part the light meets there.
bool bounce_crosses_stone(vec3 P, BounceStoneReceiver receiver, vec3 xp) {
  float tol = u_light_layer_texel_world;
  vec4 clipX = u_light_view_proj * vec4(xp, 1.0);
  for (int i = 1; i <= BOUNCE_STONE_POINTS; ++i) {
    float f = float(i) / float(BOUNCE_STONE_POINTS + 1);
    vec4 clip = mix(receiver.clip, clipX, f);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;  // off the map: air
    // The texel under uv by the sampler (the layers are GL_NEAREST, one level, clamped to the edge;
    // uv lies in [0, 1)): llvmpipe takes floor(uv x size), the texel ivec2(uv x size) names, by
    // fewer instructions than texelFetch's per-lane level and bounds checks (docs/performance.md).
    vec2 layers = textureLod(u_bounce_layers, uv, 0.0).xy;
    float d = light_distance_of(mix(P, xp, f));
    if (layers.y < 1e20 && d > layers.x + tol && d < layers.y - tol) return true;
  }
  return false;
}
