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
// dragon's thin coils; testing every receiver (s22-cross) took that and cost dragon-back 0.020
// (docs/quality.md, "Twenty-second session: the bounce through the stone against the light's entry
// and exit layers"; this rule: "Twenty-third session: ...").
// Approximations, each stated:
// - "behind" is more than BOUNCE_BEHIND_TEXELS layer texels beyond the exit of the first part at
//   the receiver's own texel (nearest read); a receiver on that part's exit face is on it, not
//   behind it. Measured 2, 6, 15: 2 the best for buddha-side, 15 loses most of it;
// - BOUNCE_STONE_POINTS points evenly spaced strictly inside the segment: a part thinner than the
//   spacing between two points is stepped over (5 points measured no better than 3);
// - the layers hold the first part along each light ray only: a second part behind it is not
//   stone to this test, nor is the air between two parts (the shade between dragon-side's coils
//   keeps its bounce, which a test against the light's one depth map removed: s22-side, -0.05);
// - a point counts as stone only more than a layer texel inside (the layers' nearest read and the
//   surfaces' slope within a texel: the segment's ends lie on the surface); off the map, or where
//   no exit lies behind the entry (LightDepthPass::kNoLayer), it is air.
// Needs from the includer: deferred_common.glsl (light_distance_of, u_light_view_proj),
// u_light_layer_texel_world (BouncePass: a texel of the layers at the object).

layout(binding = UNIT_LIGHTING_LIGHT_LAYERS) uniform sampler2D u_bounce_layers;  // entry, exit
uniform float u_light_layer_texel_world;

const int BOUNCE_STONE_POINTS = 3;
const float BOUNCE_BEHIND_TEXELS = 2.0;

// The layers (entry, exit light distances) at q's texel, and q's own light distance in z; entry
// kNoLayer (no part) off the map.
vec3 bounce_layers_at(vec3 q) {
  vec4 clip = u_light_view_proj * vec4(q, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return vec3(1e30, 1e30, 0.0);
  return vec3(texelFetch(u_bounce_layers, ivec2(uv * vec2(textureSize(u_bounce_layers, 0))), 0).xy, light_distance_of(q));
}

// True where the receiver P lies behind the first part the light meets along its ray (layers.y
// 1e30: LightDepthPass::kNoLayer, no exit: no part).
bool bounce_behind_first_part(vec3 P) {
  vec3 l = bounce_layers_at(P);
  return l.y < 1e20 && l.z > l.y + BOUNCE_BEHIND_TEXELS * u_light_layer_texel_world;
}

// True where a point of the segment from the receiver P to the emitter xp lies in the stone of the
// first part the light meets there.
bool bounce_crosses_stone(vec3 P, vec3 xp) {
  float tol = u_light_layer_texel_world;
  for (int i = 1; i <= BOUNCE_STONE_POINTS; ++i) {
    vec3 l = bounce_layers_at(mix(P, xp, float(i) / float(BOUNCE_STONE_POINTS + 1)));
    if (l.y < 1e20 && l.z > l.x + tol && l.z < l.y - tol) return true;
  }
  return false;
}
