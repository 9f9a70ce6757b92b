#version 450 core
// The bounce pass's second draw (`marble` only): the light's further bounces, gathered in screen
// space from the first bounce (bounce.glsl) that the pass's first draw left at each of its texels,
// on a grid twice as coarse each way as the first's (a 64th of the lighting pass's texels): the
// further bounces are smooth over it (the first bounce, itself smooth over tens of pixels, gathered
// again over up to half the frame), and on the first's grid this draw cost the dragon's 800²
// frames 1.06-1.08x by instructions (docs/performance.md, "Fourteenth session").
//
// Why: the first bounce's emitters are the surfaces the light sees (the reflective shadow map), but
// stone lit only by the first bounce (a crease's shadowed wall, the coils' undersides) sends light
// on too: Cycles' further bounces are 4.6 % of dragon-front's picture and 6.7 % of buddha-front's,
// a third and two fifths of its indirect light (docs/quality.md, "Twelfth session: the front- and
// side-lit scenes"). Those emitters are in the light's shadow, so the light's map cannot hold them;
// the camera's G-buffer holds the ones the camera sees, with their first bounce beside them.
//
// The second bounce (the rendering equation's next term, as in screen-space indirect lighting:
// Ritschel et al. 2009's screen-space directional occlusion, one bounce gathered from a G-buffer's
// radiance): each sample s (a G-buffer pixel) is a Lambertian emitter of radiance B1/PI = albedo x
// E1/PI (E1, the first bounce's irradiance entering s), area A_s = its sector's pixels x (a pixel's
// width at its distance)^2 / cos to the view (the cosine floored at 0.2 as the upsample's reach), and
// gives the receiver P by the point law, each sample standing for its ring sector (midpoint rule),
//   E2/PI = sum_s B1_s/PI x K_s (x the entry 41/42),  K_s = min(A_s, PI r^2) cos_s cos_P / (PI r^2).
// Not the first bounce's softened law (A / PI added to r^2, bounce.glsl: the on-axis form of a disk
// around the receiver's normal): a ring sector never holds the receiver, and an emitter the camera
// sees at grazing has A_s up to 5 sector areas, which the softened law cut by up to 6x: the fold
// test (tests/bounce_further_gl_test.cpp) read 0.61-0.69 of the analytic second bounce with it,
// 0.73-0.83 by the point law (1.07-1.13 with the series below). The min() only bounds a sector's
// view factor by its distance's hemisphere.
// The third and later bounces by the series E_{n+1} ~ albedo x F x E_n, F = sum_s K_s, the view
// factor of the stone this gather sees (the receiver's neighbourhood re-emitting its own further
// bounce: the assumption of Jimenez et al. 2016's multi-bounce fit, but with F measured per point
// instead of from ambient occlusion): E_further = E2 / (1 - albedo F). On dragon-front it adds
// 1.42x to the second bounce, Cycles' own ratio there 1.52x; in the fold test ~1.3x, where the
// fold's fourth bounce adds ~1.1x (a fold's two faces, unlike a cavity, do not see themselves).
// The albedo is applied by the pass's third draw (bounce_merge.frag.glsl), so this draw stores, per unit
// of the light's radiance, the three first-bounce terms' integrals and F:
//   rgb = sum_s K_s x (diffuse, glossy F0 part, glossy 1 - F0 part of E1_s/PI) x 41/42, a = F.
// Approximations, each stated:
// - only the emitters the camera sees: a crease's far wall hidden behind its near one sends none
//   (the further bounces come out low where the view grazes into a fold);
// - no visibility between emitter and receiver (as the first bounce: the cosines cut emitters
//   behind P's tangent plane and receivers behind the emitter's);
// - a disk of FURTHER_RADIUS of the frame's height: emitters farther away on the screen are left
//   out (the further bounces are local: a crease sees itself);
// - the series's F is the one of the visible stone around P, and assumes the further bounce's
//   level there equal to P's own.
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"
#include "rotation.glsl"
#include "nearest_texel.glsl"

layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_screen_occlusion.glsl"  // the first bounce's occlusion next to the receiver, for these samples too
layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;  // the first bounce, evened out
uniform int u_scale;         // full-resolution pixels per texel of this draw: twice the first bounce's
uniform int u_bounce_scale;  // and of the first bounce's (u_bounce)
layout(location = 0) out vec4 o_further;

// FURTHER_RINGS rings, each twice the radius of the one inside it, the outermost reaching
// FURTHER_RADIUS of the frame's height, of FURTHER_ANGLES samples at even angles; the innermost
// reaches in to 1/256 of the frame's height (3 pixels at 800). Seven rings: an eighth, in to 1.5
// pixels, cost 0.93 M more instructions of the dragon's 800² frames (an eighth of this draw)
// and changed the ten scenes within a pattern turn's noise (docs/quality.md, "Fourteenth session").
// The samples read the G-buffer at their own pixel (the
// emitter's position and normal exact), and the first bounce at the pass's texel nearest to it:
// the first bounce is smooth over a texel, the geometry is not. (Snapped to the pass's texels, the
// near rings' samples sat up to a texel farther out than the sector they stand for, and the near
// field, which dominates a crease, came out at about half: the fold test read 0.5 of the model.)
// Eight angles: four (sixteen over the 2 x 2 turns) cost ~4 ms less of the dragon's 800-pixel
// frames on llvmpipe and scored within a pattern turn's noise in the ten scenes, but read 1.71 of
// the fold test's model at one point (too few samples for a near emitter: blotches).
const int FURTHER_RINGS = 7;
const int FURTHER_ANGLES = 8;
const float FURTHER_RADIUS = 0.5;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  ivec2 fullSize = textureSize(u_depth, 0);
  ivec2 px = t * u_scale;
  // The background: alpha -1, which the merge's upsample leaves out (bounce_bilateral.glsl).
  if (any(greaterThanEqual(px, fullSize))) {
    o_further = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  float depth = nearest_texel(u_depth, px).r;  // px inside the frame (above): the same bits as texelFetch
  if (depth >= 1.0) {
    o_further = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  vec2 full = vec2(fullSize);
  vec3 P = surface_point((vec2(px) + 0.5) / full, depth);
  vec3 N = decode_normal(nearest_texel(u_normal, px).xy);
  // A pixel's world width per unit of distance from the camera (at P; across the frame it changes
  // by the off-axis angle's cosine, under 6 % at 36 degrees of view: the emitters' areas by 12 %).
  float width_per_distance = length(surface_point((vec2(px) + vec2(1.5, 0.5)) / full, depth) - P) / distance(P, u_camera_pos);
  ivec2 size = textureSize(u_bounce, 0);
  float outer = FURTHER_RADIUS * full.y;  // in full-resolution pixels
  // The first draw's interleaving (bounce_gather.frag.glsl), for the same reason: each texel of a
  // 2 x 2 block turns the pattern by another quarter step; the pass then evens the four turns out
  // over the blocks with the first bounce's draw (bounce_deinterleave.frag.glsl).
  ivec2 q = t & 1;
  float turn = 0.25 * float(q.x + 2 * q.y);
  vec4 sum = vec4(0.0);
  // Sample k of ring `ring` at angle 2 PI (k + turn + 0.381966 ring) / FURTHER_ANGLES, by rotation
  // (rotation.glsl).
  const float step = 2.0 * PI / float(FURTHER_ANGLES);
  const vec2 byStep = vec2(cos(step), sin(step)), byRing = vec2(cos(0.381966 * step), sin(0.381966 * step));
  vec2 ringDir = vec2(cos(step * turn), sin(step * turn));
  for (int ring = 0; ring < FURTHER_RINGS; ++ring) {
    float r0 = outer * exp2(float(ring - FURTHER_RINGS)), r1 = 2.0 * r0;
    float r = 0.5 * (r0 + r1);
    float sector = PI * (r1 * r1 - r0 * r0) / float(FURTHER_ANGLES);  // in full-resolution pixels
    vec2 next = ringDir;
    ringDir = rotate2(ringDir, byRing);
    for (int k = 0; k < FURTHER_ANGLES; ++k) {
      vec2 dir = next;
      next = rotate2(next, byStep);  // before any `continue`
      ivec2 ps = px + ivec2(round(r * dir));
      if (any(lessThan(ps, ivec2(0))) || any(greaterThanEqual(ps, fullSize))) continue;
      // ps's depth and normal through the samplers at its centre (GL_NEAREST: nearest_texel.glsl).
      vec2 uvs = (vec2(ps) + 0.5) / full;
      float ds = textureLod(u_depth, uvs, 0.0).r;
      if (ds >= 1.0) continue;  // the background
      vec3 Ps = surface_point(uvs, ds);
      vec3 Ns = decode_normal(textureLod(u_normal, uvs, 0.0).xy);
      vec3 d = P - Ps;
      float r2 = max(dot(d, d), 1e-12);
      float cosS = dot(Ns, d);   // x |d|
      float cosP = -dot(N, d);   // x |d|
      if (cosS <= 0.0 || cosP <= 0.0) continue;  // first: most samples stop here, before two more reads
      // No light (and no view factor for the series) whose way runs into the stone next to the
      // receiver: the first bounce's test (bounce_screen_occlusion.glsl; session 22).
      if (bounce_occluded_near_receiver(P, Ps)) continue;
      ivec2 ts = min((ps + u_bounce_scale / 2) / u_bounce_scale, size - 1);  // the nearest texel of the first bounce
      vec4 b = nearest_texel(u_bounce, ts);
      if (b.a < 0.0) continue;
      // That texel's first bounce is the emitter's only if it lies on the same surface: near a fold
      // or a part seen edge-on (a plate's top seen at grazing, a few pixels high) the nearest texel
      // can be the other face's, whose light the emitter does not have (the corner tests' wall face
      // then received its own first bounce back through the plate: +26 %). Normals over 37 degrees
      // apart: left out (too little rather than light that is not there).
      if (dot(Ns, decode_normal(nearest_texel(u_normal, ts * u_bounce_scale).xy)) < 0.8) continue;
      vec3 toCamera = u_camera_pos - Ps;
      float dist = length(toCamera);
      float w = width_per_distance * dist;
      float cosV = max(abs(dot(Ns, toCamera)) / dist, 0.2);
      float A = sector * w * w / cosV;
      float K = min(A, PI * r2) * cosS * cosP / (r2 * PI * r2);
      sum += K * vec4(b.xyz, 1.0);
    }
  }
  o_further = vec4(sum.xyz * (41.0 / 42.0), sum.w);
}
