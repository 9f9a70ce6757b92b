// The bounce's visibility through another part's stone (session 23; the through-stone test is
// session 22's s22-cross, after session 19's bounce_crosses_stone, commit 435f961): a receiver
// that lies behind the first part the light meets (in that part's shadow: a fold of the robe
// behind the raised arm, the body behind a fold) takes no bounce whose way from the emitter
// passes through that part's stone. Tested at BOUNCE_STONE_POINTS points of the segment against
// the light's entry and exit layers (light_layers.frag.glsl: a point whose light distance lies
// between the texel's entry and exit is in that part's stone; beyond the exit it is in the air
// behind the part, before the entry in the air in front of it).
// Why only behind the first part: light from a lit surface that reaches such a receiver through the
// stone leaves that part through its exit face first: it is that part's transmission (its glow,
// lighting.frag.glsl), which the reflective shadow map does not hold as an emitter, and for the
// statues' thick parts it is nothing (T(20 mm) / R_inf = 0.006, session 10's slab fit). A receiver
// on the first part itself (its own exit side) keeps the light through its own stone: there it
// stands in for the part's own glow, which marble's transmission leaves short on the back-lit
// dragon's thin coils; testing every receiver (s22-cross) took that and cost dragon-back 0.016 on
// session 22's main, where testing only the receivers behind a part costs it 0.0019 and keeps all of
// buddha-side's gain (+0.0040; docs/quality.md, "Twenty-third session: the bounce through another
// part's stone, for receivers in that part's light shadow").
// Cost: on llvmpipe the gate saves nothing (a draw's lanes take both ways), so every receiver pays
// the per-sample test: +12.5 M instructions of the dragon's 800² camera frame (docs/performance.md).
// Approximations, each stated:
// - "behind" is more than BOUNCE_BEHIND_TEXELS layer texels beyond the exit of the first part at
//   the receiver's own texel (nearest read); a receiver on that part's exit face is on it, not
//   behind it. Measured 2, 6, 15: 2 the best for buddha-side, 15 loses most of it;
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

// What the test needs of the receiver, computed once per gather (bounce_gather): whether it lies
// behind the first part, and its light-clip position, which the way's points interpolate (clip
// coordinates are linear in the position: one projection per sample, the emitter's).
struct BounceStoneReceiver {
  bool behind;
  vec4 clip;  // u_light_view_proj * P
};

// The layers' texel under a light-clip position (-1 off the map).
ivec2 bounce_layers_texel(vec4 clip) {
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return ivec2(-1);
  return ivec2(uv * vec2(textureSize(u_bounce_layers, 0)));
}

// P behind the first part the light meets along its ray (layers.y 1e30: LightDepthPass::kNoLayer,
// no exit: no part)?
BounceStoneReceiver bounce_stone_receiver(vec3 P, vec4 clipP) {
  ivec2 t = bounce_layers_texel(clipP);
  float exitDistance = t.x < 0 ? 1e30 : nearest_texel(u_bounce_layers, t).y;
  return BounceStoneReceiver(exitDistance < 1e20 && light_distance_of(P) > exitDistance + BOUNCE_BEHIND_TEXELS * u_light_layer_texel_world, clipP);
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
