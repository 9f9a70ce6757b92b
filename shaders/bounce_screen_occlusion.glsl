// The camera-side bounce's occlusion near the receiver (session 22): a sample of the one bounce
// (bounce.glsl, bounce_sample) brings nothing where its way from the receiver to the emitter passes
// just behind a surface the camera sees, i.e. runs into stone, at an eighth, a quarter or three
// eighths of the way (since session 26; an eighth alone before). Points of the segment tested
// against the camera's depth buffer, as screen-space directional occlusion does for its sample
// directions (Ritschel, Grosch & Seidel 2009, "Approximating dynamic global
// illumination in image space"); the reflective shadow map itself has no visibility.
// Why: in the side-lit statues' shade the bounce was 1.6-1.9 x Cycles' indirect light (buddha-side's
// darkest band of Cycles' display luma, against the averaged references), light gathered from lit
// surfaces whose way to the shaded side runs into the stone first (the robe's folds, the far side of
// the body seen edge-on); docs/quality.md, "Twenty-second session: the side-lit shade against the
// averaged references".
// Approximations, each stated:
// - BOUNCE_OCCLUSION_POINTS points, at 1, 2, ... eighths of the segment from the receiver: the stone
//   next to the receiver (a fold's wall, the body beyond an edge) and a wall up to three eighths of
//   the way out are caught, one halfway to the emitter or beyond is not (session 19's and 20's tests
//   through the light's layers caught it, and removed the light through the back-lit dragon's coils
//   that stands in for its missing glow: dragon-back -0.012 to -0.031). Session 22 measured one
//   point on dragon-side, buddha-side, dragon-back and buddha-front at 1/20, 1/10, 1/8, 3/20, 7/40
//   and 1/5 of the segment and at fixed 1.5-6 % of the object's size, then over all ten reference
//   scenes: 1/8 the best (buddha-side +0.012, the ten scenes' mean +0.0019). Session 26 found the
//   side-lit statues' remaining bounce surplus where the first bounce dominates (1.2-2.1 x Cycles'
//   indirect light where it is over nine tenths of marble's bounce, against 0.7-0.8 x where the
//   further bounces dominate: a first bounce through stone farther out than an eighth) and measured
//   1/8 + 2/8, 1/8 + 2/8 + 3/8, 1/8 + 4/8, 1/8 to 4/8, 1/8 to 6/8 and sixteenths up to 6/16 and
//   8/16: three eighths the best for the cost (dragon-side +0.0013, buddha-side +0.0030,
//   dragon-back +0.0040, the ten scenes' mean +0.0011, none down by more than 0.0002; at 6/8 the
//   points fall behind parts in front, taken for stone, and dragon-side loses it); docs/quality.md,
//   "Twenty-sixth session: the side-lit statues' indirect light split into first, further and
//   crossed bounces";
// - a point within BOUNCE_OCCLUSION_NEAR tolerances of the receiver is not tested (the inner rings'
//   ways, whose eighth hardly leaves the receiver: the surface seen there is the receiver's own,
//   and at a grazing view its slope across the pixel could pass for stone). At 2, 4 and 8 the four
//   scenes above moved by at most 0.0006, 4 the best; it saves no instructions on llvmpipe (the
//   lanes of a draw take both ways);
// - "just behind" is BOUNCE_OCCLUSION_DEPTH in world units (the object is normalized to 2 units
//   across, so 4 % of its size): the surface the camera sees in front of the point is taken to be
//   at least that thick (screen-space occlusion's usual thickness assumption). Further behind, the
//   point is taken to be in the air behind a part in front (a coil before another), not in stone;
// - a point the camera cannot place (off screen, or over the background) is not occluded;
// - tolerance two light-map texels (u_light_texel_world) against the depth buffer's own error;
// - view-dependent: only the camera-side gathers test it (bounce_gather.frag.glsl,
//   bounce_refine_gather.comp.glsl); the light-side entries (bounce_entry.frag.glsl) have no
//   camera and keep the bounce without it.
// Needs from the includer: deferred_common.glsl (surface_point, u_view_proj, u_camera_pos,
// u_light_texel_world) and the G-buffer's depth bound as u_depth.

const float BOUNCE_OCCLUSION_STEP = 0.125;  // of the receiver -> emitter segment, between the points
const int BOUNCE_OCCLUSION_POINTS = 3;
const float BOUNCE_OCCLUSION_DEPTH = 0.08;  // world units behind the seen surface that count as stone
const float BOUNCE_OCCLUSION_NEAR = 4.0;    // tolerances: a point nearer the receiver is not tested

// True where any of the BOUNCE_OCCLUSION_POINTS points of the way nearest the receiver, at 1, 2, ...
// BOUNCE_OCCLUSION_STEP of the way from the receiver P to the emitter xp, lies behind the surface
// the camera sees there by more than the tolerance and less than BOUNCE_OCCLUSION_DEPTH. The points'
// clip coordinates by interpolating the two ends' (a projective map keeps straight lines straight in
// homogeneous coordinates): two matrix products per sample for any number of points.
bool bounce_occluded_near_receiver(vec3 P, vec3 xp) {
  float tol = 2.0 * u_light_texel_world;
  vec3 d = xp - P;
  float nearAt2 = BOUNCE_OCCLUSION_NEAR * BOUNCE_OCCLUSION_NEAR * tol * tol / max(dot(d, d), 1e-12);
  vec4 clipP = u_view_proj * vec4(P, 1.0), clipX = u_view_proj * vec4(xp, 1.0);
  // Depths along the camera's axis (clip w), the seen surface's from the inverse's w row alone
  // (surface_point's w: 1 / clip w): under 7 % off the distances along the ray at the frame's corners.
  vec4 wRow = vec4(u_inv_view_proj[0][3], u_inv_view_proj[1][3], u_inv_view_proj[2][3], u_inv_view_proj[3][3]);
  for (int i = 1; i <= BOUNCE_OCCLUSION_POINTS; ++i) {
    float at = BOUNCE_OCCLUSION_STEP * float(i);
    if (at * at < nearAt2) continue;  // within BOUNCE_OCCLUSION_NEAR tolerances of the receiver
    vec4 clip = mix(clipP, clipX, at);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) continue;
    float depth = textureLod(u_depth, uv, 0.0).r;  // the nearest pixel: the G-buffer's depth is GL_NEAREST
    if (depth >= 1.0) continue;
    float behind = clip.w - 1.0 / dot(wRow, vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0));
    if (behind > tol && behind < BOUNCE_OCCLUSION_DEPTH) return true;
  }
  return false;
}
