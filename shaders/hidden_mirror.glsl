// The mirror image of the stone the camera cannot see (`marble` mode, lighting pass): where the
// screen-space march of the mirror ray (self_reflection.glsl) finds no surface on screen -- most
// often because it passes behind a part -- the ray is marched again in the light's space, against
// the light's exit layer (light_exit.frag.glsl: where the light leaves the first part it meets)
// and its distance map (where it entered that part). Where the ray crosses an exit face from the
// air behind it, it meets a surface that glows with the light carried through the part, and
// that surface's transmitted radiance, weighted by the self-reflection's mirror weight (Fresnel's
// exact factor at the view's cosine), is what the surface mirrors. Back-lit, these are the
// camera-facing sides of the parts behind the rims and creases, whose mirror rays run away from
// the camera behind the part in front (docs/quality.md, "Nineteenth session: what dragon-back's
// and buddha-back's gap is made of": the screen march passes behind a part for 45 % / 52 % of
// Cycles' mirror image on dragon-back / buddha-back; Cycles' image added there alone was worth
// +0.017 / +0.026 SSIM). Session 19's first try estimated the light at the step's middle from
// the one-layer map, which counts the air between parts as stone (0.03 of the right light on a
// wall facing a glowing block); with the exit layer the ray finds the face itself.
//
// The march (design, each choice stated):
// - the ray P + t R in the light's clip space (linear in homogeneous coordinates, as the screen
//   march's), at HIDDEN_MIRROR_STEPS points, the first one exit-layer texel out, each step
//   HIDDEN_MIRROR_GROWTH times the last: 20 points reach 57 texels (1.55 scene units at the
//   layer's 2.7 mm texel: the normalised mesh is 2 units across), the last step 6 texels long, so
//   a part narrower than that in the light's view may be stepped over far from P;
// - a point is in the stone where its light distance lies between the entry (the distance map,
//   nearest texel) and the exit (the exit layer, nearest texel) by more than a layer texel (their
//   point sampling and the surfaces' slope within a texel, the tolerance of session 19's
//   visibility test); beyond the exit it is in the air behind the first part, before the entry
//   in the air in front of it;
// - a hit: the segment from the last point to this one crosses this texel's exit distance from
//   behind (the last point farther from the light than the exit, this one nearer), this texel
//   holds a part (entry before exit), and the segment reaches the part (this point no farther in
//   front of the entry than the segment is long: a segment that crosses the whole slab in one
//   step still met its exit face first). Only after the ray has been in the air (a point off the
//   stone by a texel): P's own surface, quantised by the layer, is not a hit;
// - the ray stops without a hit where it is in the stone without having crossed an exit (it
//   entered through a face toward the light or the part's side in the light's view: the bounce's
//   mirrored part, from the light's map, holds the lit faces), where it leaves the light's map (the
//   map spans the object's bounding sphere: nothing of the object lies beyond) or goes behind the
//   light, and after its last point;
// - only the first part along each light ray: a second part behind it (the body behind a coil,
//   seen from the light) neither glows here nor blocks the ray, nor does P's own part where the
//   first part is another (its concave side re-met by the ray).
// The radiance leaving the exit face X (where the segment crosses the exit distance, linearly
// between the two points): the transmission's straight model there (lighting.frag.glsl,
// marble_entering: the light entering at the distance map's bilinear entry, at its stored cosine
// with the Principled coupling, carried the chord s = exit - entry by the random walk's slab
// transport, per channel: T's hue; its falloff at the entry), as light entering the stone, before
// the albedo: the post pass multiplies it by P's albedo, taken as the hit's (the self-reflection's
// and the bounce's mirrored part's choice; exact for a flat stone). Not the transmission's ring
// gather, which reads 24 entries: over 3 mm chords the straight model is 1.2-2.8x the gather on
// curved parts (teapot-back's 5-20 mm, "Eleventh session"), where T is small; nor the hit's own
// bounce and direct light (an exit face faces away from the light). The result joins the light
// entering at P, so the subsurface blur spreads it as it does the bounce's mirrored part (session
// 19: the mirrored part unblurred moved SSIM by under 0.001).
// Cost: it runs only where the screen march found nothing (self_reflection_hit's -1); the exit
// layer is drawn with the light's map, only when the light's map is.
// Needs from the includer: u_light_distance, u_light_view_proj, u_light_texel_world,
// light_distance_of, light_irradiance, light_entry_at, slab_transport, principled_entry,
// u_mm_per_unit, u_translucency.

layout(binding = UNIT_LIGHTING_LIGHT_EXIT) uniform sampler2D u_light_exit;

const int HIDDEN_MIRROR_STEPS = 20;
const float HIDDEN_MIRROR_GROWTH = 1.1;

// The light P's mirror ray (direction R) meets on an exit face hidden from the camera (.rgb:
// light leaving it as light entering the stone, before the albedo; .a = 1), or vec4(0) where it
// meets none.
vec4 hidden_mirror(vec3 P, vec3 R) {
  ivec2 exitSize = textureSize(u_light_exit, 0), mapSize = textureSize(u_light_distance, 0);
  float texel = u_light_texel_world * float(mapSize.x) / float(exitSize.x);  // the layer's texel
  vec4 clipP = u_light_view_proj * vec4(P, 1.0), clipR = u_light_view_proj * vec4(R, 0.0);
  float t = texel, step = texel;
  float lastT = 0.0, lastL = light_distance_of(P);
  bool aired = false;  // the ray has been off the stone by a texel
  for (int i = 0; i < HIDDEN_MIRROR_STEPS; ++i) {
    vec4 clip = clipP + t * clipR;
    if (clip.w <= 0.0) break;  // behind the light
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) break;  // off the map
    float exitD = texelFetch(u_light_exit, ivec2(uv * vec2(exitSize)), 0).r;
    float entryD = texelFetch(u_light_distance, ivec2(uv * vec2(mapSize)), 0).r;
    float l = light_distance_of(P + t * R);
    bool part = entryD < exitD;  // kNoExit and the map's "nothing hit" both read as no part
    if (aired && part && lastL > exitD && l <= exitD && l >= entryD - (lastL - l)) {
      // The exit face, where the segment crosses its distance.
      vec3 X = P + mix(lastT, t, (lastL - exitD) / max(lastL - l, 1e-9)) * R;
      vec3 e = light_entry_at(X);
      float s = max(exitD - e.x, 0.0);
      vec3 light = e.z > 0.0 ? light_irradiance(e.x) / PI * (e.y * principled_entry(e.y)) *
                                   slab_transport(s * u_mm_per_unit) * u_translucency
                             : vec3(0.0);
      return vec4(light, 1.0);
    }
    bool stone = part && l > entryD + texel && l < exitD - texel;
    if (aired && stone) break;  // in the stone, not through an exit face
    aired = aired || !(part && l > entryD - texel && l < exitD + texel);
    lastT = t;
    lastL = l;
    step *= HIDDEN_MIRROR_GROWTH;
    t += step;
  }
  return vec4(0.0);
}
