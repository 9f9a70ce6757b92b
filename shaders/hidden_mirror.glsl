// The mirror image of the stone the camera cannot see (`marble` mode, lighting pass): where the
// screen-space march of the mirror ray (self_reflection.glsl) finds no surface on screen -- most
// often because it passes behind a part -- the ray is marched again in the light's space, against
// the light's entry and exit layers (light_layers.frag.glsl: where the light enters and leaves
// the first part it meets). Where the ray crosses an exit face from the
// air behind it, it meets a surface that glows with the light carried through the part, and
// that surface's transmitted radiance, weighted by the self-reflection's mirror weight (Fresnel's
// exact factor at the view's cosine), is what the surface mirrors. Back-lit, these are the
// camera-facing sides of the parts behind the rims and creases, whose mirror rays run away from
// the camera behind the part in front (docs/quality.md, "Nineteenth session: what dragon-back's
// and buddha-back's gap is made of": the screen march passes behind a part for 45 % / 52 % of
// Cycles' mirror image on dragon-back / buddha-back; Cycles' image added there alone was worth
// +0.017 / +0.026 SSIM). Session 19's first try estimated the light at the step's middle from
// the one-layer map, which counts the air between parts as stone (0.03 of the right light on a
// wall facing a glowing block); with the exit layer the ray finds the face itself
// (tests/hidden_mirror_gl_test.cpp: 0.89 of the face's mirror image seen on screen).
//
// The march (design, each choice stated):
// - the ray P + t R in the light's clip space (linear in homogeneous coordinates, as the screen
//   march's), at HIDDEN_MIRROR_STEPS points spaced geometrically (the first HIDDEN_MIRROR_FIRST
//   layer texels out, each step HIDDEN_MIRROR_GROWTH times the last): 12 points reach 58 texels
//   of the layers (0.78 scene units at their 1.35 mm texel; the normalised mesh is 2 units
//   across), the last step 9 texels long, so a part narrower than that in the light's view may be
//   stepped over far from P. Against the ten reference scenes (docs/quality.md, "Twenty-second
//   session"): reaching 0.45 units lost 0.008 on buddha-back; 1.55 or 2.4 units gained nothing;
// - the four texels of a 2 x 2 quad share their marches: texel k marches the k-th quarter of
//   its own ray's points (and the point before it, for the crossing), and the quad takes the
//   first quarter, in order along the ray, that meets something: each texel pays a quarter of the
//   march, and the quad's rays (two full-resolution pixels apart) stand in for each other beyond
//   the first quarter. A quarter is left out where its texel is off the object;
// - a point is in the stone where its light distance lies between the entry (the nearest surface)
//   and the exit of the layers' texel (nearest) by more than a layer texel (their point sampling and the surfaces'
//   slope within a texel, the tolerance of session 19's visibility test); beyond the exit it is in
//   the air behind the first part, before the entry in the air in front of it;
// - a hit: the segment from the last point to this one crosses this texel's exit distance from
//   behind (the last point farther from the light than the exit, this one nearer), this texel
//   holds a part (entry before exit), and the segment reaches the part (this point no farther in
//   front of the entry than the segment is long: a segment that crosses the whole slab in one
//   step still met its exit face first). In the first quarter only after the ray has been in the
//   air (a point off the stone by a texel): P's own surface, quantised by the layers, is not a hit;
// - a side hit: the ray is in the stone without having crossed an exit, and the last point was
//   already deeper along the light than this texel's entry (so it lay beside the part in the
//   light's view): it entered through the part's side, edge-on to the light -- most of the
//   dragon's coils seen from the camera behind them, where dragon-back's missing rim lines are
//   (docs/quality.md, "Twenty-second session: a second pair of light layers"). That face glows
//   with the light carried from the entry down to the point's depth (the chord s = l - entry);
// - the ray stops without a hit where it is in the stone through a face toward the light (the
//   last point no deeper than the entry: the bounce's mirrored part, from the light's map, holds
//   the lit faces), where it leaves the light's map (the
//   map spans the object's bounding sphere: nothing of the object lies beyond) or goes behind the
//   light, and after its last point;
// - only the first part along each light ray: a second part behind it (the body behind a coil,
//   seen from the light) neither glows here nor blocks the ray, nor does P's own part where the
//   first part is another (its concave side re-met by the ray). A second pair of layers (the
//   second part's entry and exit, depth-peeled) was measured and not kept: light carried through
//   two parts is negligible in the reference scenes (0.0000 of dragon-back's picture), for a new
//   draw costing the light frame +55 M instructions (docs/quality.md, "Twenty-second session: a
//   second pair of light layers").
// The radiance leaving the exit face X (where the segment crosses the exit distance, linearly
// between the two points; for a side hit, the point in the stone at its own depth, the chord to
// it: an approximation -- a side point at depth s taken to glow as a slab's exit after s, so
// light that leaves through the side nearer the entry is not counted; the point is up to a
// step beyond the face, so s up to a step long -- against the ten scenes the depth half a
// step nearer lost 0.0002 mean SSIM): the transmission's straight model there (lighting.frag.glsl,
// marble_entering: the light entering at the distance map's bilinear entry, at its stored cosine
// with the Principled coupling, carried the chord s = exit - entry by the random walk's slab
// transport, per channel: T's hue; its falloff at the entry), as light entering the stone, before
// the albedo: the post pass multiplies it by P's albedo, taken as the hit's (the self-reflection's
// and the bounce's mirrored part's choice; exact for a flat stone). Not the transmission's ring
// gather, which reads 24 entries: over 3 mm chords the straight model is 1.2-2.8x the gather on
// curved parts (teapot-back's 5-20 mm, "Eleventh session"), where T is small; nor the hit's own
// direct light (an exit face faces away from the light).
// The face's indirect light (since session 23): the face also sends what the bounces bring it,
// which the layers cannot gather; it is taken as P's own diffuse bounce (marble_bounce without its
// mirrored part; lighting.frag.glsl's main adds it to this light): the face lies across a crease or
// behind a part from P, millimetres to a third of the object away, where the bounces' light changes
// slowly (their emitters are the whole lit side). Against Cycles' mirror image (session 19's
// camera-specular split) where the march meets an exit face, marble's light there was 0.45 / 0.69
// of Cycles' on dragon-back / buddha-back without it; with it dragon-back +0.0009, buddha-back and
// teapot-back +0.0004 SSIM, no scene down more than 0.0001 (docs/quality.md, "Twenty-third session:
// the mirrored highlights ..."). Error: P's bounce for the face's, exact where the two receive
// alike; low where P lies deep in a crease and the face in the open, high the other way round.
// The result joins the light
// entering at P, so the subsurface blur spreads it as it does the bounce's mirrored part (session
// 19: the mirrored part unblurred moved SSIM by under 0.001).
// Cost: a quad marches only where one of its texels' screen march found nothing
// (self_reflection_hit's -1) and its ray comes nearer the light (lighting.frag.glsl, main), each
// texel a quarter of the points, one read of the layers a point; the layers are drawn with the
// light's map, only when the light's map is (LightDepthPass). Camera frame of the dragon at 800^2
// +4 % (docs/performance.md, "Twenty-second session: the hidden mirror image"); with the side hit
// and the glow computed at one call site after the loop, the lighting pass 103.09 -> 94.93 M
// instructions (docs/performance.md, "Twenty-second session: a second pair of light layers").
// Needs from the includer: u_light_distance, u_light_view_proj, u_light_texel_world,
// light_distance_of, light_irradiance, light_entry_at, slab_transport, principled_entry,
// u_mm_per_unit, u_translucency, quad_across_x, quad_across_y, u_lit_face_ring_mm.

layout(binding = UNIT_LIGHTING_LIGHT_LAYERS) uniform sampler2D u_light_layers;  // entry, exit

const int HIDDEN_MIRROR_STEPS = 12;     // 3 per texel of the quad
const float HIDDEN_MIRROR_FIRST = 2.0;  // layer texels
const float HIDDEN_MIRROR_GROWTH = 1.15;

// The light leaving the stone after the chord s (scene units) from the entry e (light_entry_at:
// distance, cosine, found), as light entering the stone before the albedo: the transmission's
// straight model (below).
vec3 exit_glow(vec3 e, float s) {
  return light_irradiance(e.x) / PI * (e.y * principled_entry(e.y)) * slab_transport(s * u_mm_per_unit) *
         u_translucency;
}

// What quarter k of P's mirror ray (direction R) meets (hidden_mirror_shared): .a 1 an exit face
// (.rgb its light, as light entering the stone before the albedo), 2 the stone otherwise (a
// face toward the light, or a part's side), 0 nothing.
vec4 hidden_mirror_quarter(vec3 P, vec3 R, int k) {
  ivec2 size = textureSize(u_light_layers, 0);
  float texel = u_light_texel_world * float(textureSize(u_light_distance, 0).x) / float(size.x);
  vec4 clipP = u_light_view_proj * vec4(P, 1.0), clipR = u_light_view_proj * vec4(R, 0.0);
  const int PER = HIDDEN_MIRROR_STEPS / 4;
  // Point i at t_i = first (g^(i+1) - 1) / (g - 1); this quarter's points are k PER ... k PER + PER - 1,
  // and the one before (P itself for the first quarter).
  float first = HIDDEN_MIRROR_FIRST * texel, g = HIDDEN_MIRROR_GROWTH;
  float step = first * pow(g, float(k * PER));
  float lastT = (step - first) / (g - 1.0);
  float t = lastT + step;
  float lastL = light_distance_of(P + lastT * R);
  bool aired = k > 0;  // beyond the first quarter, the ray has left P's surface
  // What the march met (.a of the result) and, for a face, the point X on it and its depth along
  // the light: the glow is computed once, after the loop, for both kinds of face (llvmpipe runs a
  // branch for the whole block of lanes where any lane takes it: one call site, not two in the loop).
  float met = 0.0, depth = 0.0;
  // The point X = P + x_t R the march met, made once after the loop from its parameter x_t, not in
  // the loop's branches, which llvmpipe runs at every step for the whole block of lanes (the same
  // X, the dragon's 800^2 camera frame 0.3 M instructions fewer; docs/performance.md, "Thirtieth
  // session: ... s30-cost").
  float x_t = 0.0;
  for (int i = 0; i < PER; ++i) {
    vec4 clip = clipP + t * clipR;
    if (clip.w <= 0.0) break;  // behind the light
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) break;  // off the map
    vec2 layers = textureLod(u_light_layers, uv, 0.0).xy;  // the texel ivec2(uv x size): GL_NEAREST (nearest_texel.glsl)
    float l = light_distance_of(P + t * R);
    bool part = layers.x < layers.y;  // LightDepthPass::kNoLayer in either: no part
    if (aired && part && lastL > layers.y && l <= layers.y && l >= layers.x - (lastL - l)) {
      // The exit face, where the segment crosses its distance.
      x_t = mix(lastT, t, (lastL - layers.y) / max(lastL - l, 1e-9));
      depth = layers.y;
      met = 1.0;
      break;
    }
    bool stone = part && l > layers.x + texel && l < layers.y - texel;
    if (aired && stone) {
      // In the stone, not through an exit face. Through a face toward the light (the last point
      // no deeper than this texel's entry): nothing here. Through the part's side (the last point
      // already deeper: it was beside the part in the light's view): the side's glow, at the
      // point's own depth.
      x_t = t;
      depth = l;
      met = lastL <= layers.x + texel ? 2.0 : 1.0;
      break;
    }
    aired = aired || !(part && l > layers.x - texel && l < layers.y + texel);
    lastT = t;
    lastL = l;
    step *= g;
    t += step;
  }
  if (met != 1.0) return vec4(0.0, 0.0, 0.0, met);
  vec3 X = P + x_t * R;
  vec3 e = light_entry_at(X);
  return vec4(e.z > 0.0 ? exit_glow(e, max(depth - e.x, 0.0)) : vec3(0.0), 1.0);
}

// The light P's mirror ray meets on an exit face hidden from the camera, shared across the 2 x 2
// quad (.rgb: light leaving it as light entering the stone, before the albedo; .a = 1), or vec4(0)
// where it meets none. `marches`: this texel is on the object and its screen march found nothing
// (the quad marches where any texel of it does). Must run in uniform control flow (derivatives,
// lighting.frag.glsl's quad_across_x/y): main() calls it before any texel returns.
vec4 hidden_mirror_shared(bool stone, bool marches, vec3 P, vec3 R) {
  vec4 any_ = vec4(marches ? 1.0 : 0.0);
  any_ = max(any_, quad_across_x(any_));
  any_ = max(any_, quad_across_y(any_));
  int lane = (int(gl_FragCoord.x) & 1) + 2 * (int(gl_FragCoord.y) & 1);
  vec4 mine = vec4(0.0);
  if (any_.x > 0.0) mine = hidden_mirror_quarter(P, R, lane);  // a branch the quad takes together
  mine = stone && !any(isnan(mine)) ? mine : vec4(0.0);
  vec4 x = quad_across_x(mine), y = quad_across_y(mine), xy = quad_across_y(x);
  // By quarter: quarter q is lane q's; lane ^ 1 is across x, lane ^ 2 across y, lane ^ 3 both. Chosen
  // by selects, not read from an array indexed by the lane, which llvmpipe reads lane by lane: the
  // lighting pass of the dragon's 800^2 camera frame 0.83 M instructions fewer (docs/performance.md,
  // "Twenty-ninth session: ... s29-cost").
  vec4 found = vec4(0.0);
  for (int q = 3; q >= 0; --q) {
    int from = q ^ lane;
    vec4 v = from == 0 ? mine : from == 1 ? x : from == 2 ? y : xy;
    found = v.a > 0.5 ? v : found;  // the earliest quarter that meets something wins
  }
  return found.a > 0.5 && found.a < 1.5 ? found : vec4(0.0);
}

// The lit face hidden behind an on-screen mirror hit (mirror_lit_face.glsl): where the screen march's
// point behind its hit pixel (hit_t, self_reflection_hit) lies behind the visible face and at the
// light's entry surface, the face the ray meets is that lit one, and its light is the direct light
// entering it, as the lighting pass gives a lit face it sees (marble_surface_entering: E cos
// principled_entry / pi; the entry's distance and cosine from the light map's texel above the point,
// as thickness_at reads it), spread by the walk over a ring of the light map's texels around it as the
// blur spreads a face the camera sees (mirror_lit_face.glsl, lit_face_spread); its indirect light is taken as P's diffuse bounce, as for the exit faces
// above. Returns (light, 1) there, else 0. Tried only for rays that come nearer the light and run
// away from the camera (R.V < 0: P's N.V below 0.71, the grazing parts where a ray gets behind a face
// the camera sees; the teapot's line: R.L 0.77-0.81, near the silhouette): on the ten reference scenes
// the others changed no scene by more than 0.00004. Cost (docs/performance.md, "Twenty-eighth
// session: the lit face behind the mirror hit"): +3.1 M instructions of the dragon's 800^2 camera
// frame; the ring that spreads the face's light by the walk (lit_face_spread, since session 29) +1.9 M
// more ("Twenty-ninth session: the hidden lit face's light spread by the walk"). A plain `if`: on llvmpipe, which runs the draw's lanes through both ways of it, loops whose
// trip count is 0 where the work is not needed cost more here (+3.55 M with the light map's read in a
// loop of its own, +3.4 M in one loop; +2.24 M with the loop's gate never true).
vec4 hidden_lit_face_behind(ivec2 hit, float hit_t, vec3 P, vec3 R) {
  vec4 found = vec4(0.0);
  if (hit.x >= 0 && dot(R, light_vector(P)) > 0.0 && dot(R, normalize(u_camera_pos - P)) < 0.0) {
    vec3 X = P + R * hit_t;
    // View depths: the clip w of X (u_view_depth_row) against the hit pixel's surface (GL_NEAREST,
    // the hit on screen: nearest_texel.glsl).
    float gap = dot(u_view_depth_row, vec4(X, 1.0)) - linear_depth(nearest_texel(u_depth, hit).r, u_camera_near_far);
    // The light's entry above X: its distance and cosine, the light map's texel (as thickness_at).
    vec4 clip = u_light_view_proj * vec4(X, 1.0);
    vec2 entry = textureLod(u_light_distance, clip.xy / clip.w * 0.5 + 0.5, 0.0).rg;
    if (mirror_meets_lit_face(gap, light_distance_of(X) - entry.x, u_light_texel_world)) {
      // Spread by the walk as the blur spreads a face the camera sees (mirror_lit_face.glsl,
      // lit_face_spread): a ring of the light map's texels u_lit_face_ring_mm around X's.
      float ring = u_lit_face_ring_mm / u_mm_per_unit;
      float du = ring / (u_light_texel_world * float(textureSize(u_light_distance, 0).x));
      vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
      vec2 sum = vec2(0.0);
      for (int i = 0; i < LIT_FACE_RING_TAPS; ++i) {
        vec2 tap = textureLod(u_light_distance, uv + du * LIT_FACE_RING[i], 0.0).rg;  // GL_NEAREST
        sum += lit_face_ring_tap(tap.x, tap.y * principled_entry(tap.y), entry.x, ring);
      }
      found = vec4(light_irradiance(entry.x) / PI * lit_face_spread(entry.y * principled_entry(entry.y), sum), 1.0);
    }
  }
  return found;
}
