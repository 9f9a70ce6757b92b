// The bounce's visibility through the stone (session 22, after session 19's bounce_crosses_stone,
// commit 435f961): a sample of the one bounce (bounce.glsl, bounce_sample) brings nothing where
// its way from the emitter to the receiver passes through the first part the light meets, tested
// at BOUNCE_STONE_POINTS points of the segment against the light's entry and exit layers
// (light_layers.frag.glsl: a point whose light distance lies between the texel's entry and exit
// is in that part's stone; beyond the exit it is in the air behind the part, before the entry in
// the air in front of it). The light from a lit surface to a point behind the stone goes through
// the stone or not at all, and through the stone it is the transmission's (lighting.frag.glsl),
// not the bounce's. Where it reaches: the crossings far from the receiver, which
// bounce_screen_occlusion.glsl's one point at 1/8 of the way from the receiver does not test
// (buddha-side's darkest band: docs/quality.md, "Twenty-second session: the bounce through the
// stone against the light's layers").
// Approximations, each stated:
// - BOUNCE_STONE_POINTS points evenly spaced strictly inside the segment: a part thinner than the
//   spacing between two points is stepped over;
// - the layers hold the first part along each light ray only: a second part behind it (the body
//   behind a coil, seen from the light) is not stone to this test, nor is the air between two
//   parts (the shade between dragon-side's coils keeps its bounce, which a test against the
//   light's one depth map removed: s22-side's midpoint test, -0.05 there);
// - a point counts as stone only more than a layer texel inside (the layers' nearest read and the
//   surfaces' slope within a texel: the segment's ends lie on the surface); off the map, or where
//   no exit lies behind the entry (LightDepthPass::kNoLayer), it is air.
// Needs from the includer: deferred_common.glsl (light_distance_of, u_light_view_proj),
// u_light_layer_texel_world (BouncePass: a texel of the layers at the object).

layout(binding = UNIT_LIGHTING_LIGHT_LAYERS) uniform sampler2D u_bounce_layers;  // entry, exit
uniform float u_light_layer_texel_world;

#ifndef BOUNCE_STONE_POINTS
#define BOUNCE_STONE_POINTS 3
#endif

// True where a point of the segment from the receiver P to the emitter xp lies in the stone of the
// first part the light meets there (layers.y 1e30: LightDepthPass::kNoLayer, no exit behind).
bool bounce_crosses_stone(vec3 P, vec3 xp) {
  ivec2 size = textureSize(u_bounce_layers, 0);
  float tol = u_light_layer_texel_world;
  for (int i = 1; i <= BOUNCE_STONE_POINTS; ++i) {
    vec3 q = mix(P, xp, float(i) / float(BOUNCE_STONE_POINTS + 1));
    vec4 clip = u_light_view_proj * vec4(q, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;  // off the map: air
    vec2 layers = texelFetch(u_bounce_layers, ivec2(uv * vec2(size)), 0).xy;
    float d = light_distance_of(q);
    if (layers.y < 1e20 && d > layers.x + tol && d < layers.y - tol) return true;
  }
  return false;
}
