#version 450 core
// Pass 3 (paper §3, §3.2, §3.3, §4): full screen. Reads the G-buffer and the light's
// distance map and produces the render mode's picture.
#include "gbuffer.glsl"
#include "paper_shading.glsl"
#include "deferred_common.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 o_color;
// `marble` only: light that entered the stone (diffuse irradiance / PI, before albedo), for
// the screen-space subsurface blur; o_color is then not drawn (the post pass adds what the
// surface reflects). The pass binds only the output its mode uses.
layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_mirror_hit;  // `marble`: the pixel the mirror ray meets (xy), -1 none, -2 hidden

layout(binding = UNIT_LIGHTING_ALBEDO) uniform sampler2D u_albedo;
layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
layout(binding = UNIT_LIGHTING_LIGHT_DISTANCE) uniform sampler2D u_light_distance;
layout(binding = UNIT_LIGHTING_LIGHT_SHADOW) uniform sampler2DShadow u_light_shadow;

uniform vec2 u_camera_near_far;
uniform vec2 u_light_near_far;   // range of distances the light's map can hold

uniform vec3 u_sigma_t;          // extinction per scene unit, per channel
uniform float u_k_sss;
uniform float u_k_schlick;
uniform float u_metalness;
uniform int u_reflectance_first;
uniform int u_schlick_hn;
uniform int u_schlick_program;  // SchlickBlend: 0 opacity (the paper's text), 1 its program's subtraction
uniform float u_shininess;
uniform float u_oren_nayar_sigma;
// The render mode is a constant of the program (LIGHTING_MODE, defined by the lighting pass):
// one specialized program per mode runs only that mode's code (gl/program_variants.h).
#ifdef LIGHTING_MODE
const int u_mode = LIGHTING_MODE;
#else
uniform int u_mode;
#endif

// Physically based marble (mode `marble`).
uniform float u_mm_per_unit;     // millimetres per scene unit
uniform float u_lit_face_ring_mm;  // the walk's ring for a hidden lit face (subsurface_profile.h, walkRingRadiusMm)
// The random walk's slab transport cut to the material (marble::SlabTransport): ln(T / R_inf) per
// channel at optical thicknesses tau_i = u_slab_tau_max (i / (SLAB_NODES - 1))^2, tau = sigma_t s.
const int SLAB_NODES = 40;  // marble::kSlabTransportNodes
// The slab table's ln(T / R_inf) per channel as segments between nodes k and k + 1 (LightingPass):
// a segment's two ends in one indexed read per channel, not two reads of the node array: the
// lighting pass of the dragon's 800^2 camera frame 0.74 M instructions fewer (llvmpipe reads an array
// indexed per lane lane by lane; docs/performance.md, "Twenty-ninth session: ... s29-cost").
// Each segment's two floats packed into one 64-bit uniform (bits, not a value: ln T at node k in
// the low word, at node k + 1 in the high; LightingPass), so that llvmpipe's lane-by-lane read
// loads one 64-bit element per lane, not two floats: the lighting pass of the same frame 1.4 M
// fewer, the pictures byte-equal (docs/performance.md, "Thirtieth session: ... s30-cost").
uniform double u_slab_segment_r[SLAB_NODES - 1];
uniform double u_slab_segment_g[SLAB_NODES - 1];
uniform double u_slab_segment_b[SLAB_NODES - 1];
vec2 slab_segment_ends(double bits) { return uintBitsToFloat(unpackDouble2x32(bits)); }
uniform float u_slab_tau_max;
uniform vec3 u_slab_sigma_t_mm;  // extinction sigma_a + sigma_s per mm
uniform float u_translucency;
uniform float u_env_intensity;   // 0 = no environment light
// Full-resolution pixels per output texel: 1, or for `marble` the blur's scale (2 by default):
// output texel h is lit at the full-resolution pixel the subsurface blur takes it to stand for
// (blur_texel.glsl).
uniform int u_scale;
#include "blur_texel.glsl"

// MODE_PAPER, MODE_MARBLE, ...: marble::RenderMode's numbers (render/shader_constants.h).

// Distance the light travelled inside the object before leaving at p (GPU Gems 1, 16.3):
// the light's map holds where it entered; p is where it leaves.
float thickness_at(vec3 p) {
  vec4 clip = u_light_view_proj * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 0.0;
  float entered = texture(u_light_distance, ndc.xy * 0.5 + 0.5).r;
  return max(light_distance_of(p) - entered, 0.0);
}

#include "marble_shading.glsl"
#include "shadow_receiver_plane.glsl"  // the light entering the stone: its visibility
#include "environment.glsl"
#include "marble_light.glsl"
#include "bounce_upsample.glsl"
#include "bounce_entry.glsl"
#include "self_reflection.glsl"
#include "mirror_march_phase.glsl"
#include "mirror_lit_face.glsl"
#include "transmission_chord.glsl"  // the four texels of the light's map; the transmission's chord
#include "chord_footprint.glsl"     // where the chord is read at a rim; the walk's footprint of a short chord

// Where the light entered the stone along the light's ray through p, read from the light's map
// as transmission_thickness() does (the four texels around p, bilinear, texels that saw nothing
// left out): .x its distance from the light, .y the cosine it entered at, .z the share of the
// four texels' bilinear weight that saw the object (0 off the map or beyond the light's
// silhouette: no light enters there; fractional across the silhouette, so a tap's weight fades
// over a texel instead of switching).
vec3 light_entry_at(vec3 p) {
  vec4 entered, cosines;
  vec4 w = light_texels_at(p, entered, cosines);
  float weight = w.x + w.y + w.z + w.w;
  if (weight <= 0.0) return vec3(0.0);
  return vec3(dot(w, entered) / weight, dot(w, cosines) / weight, weight);
}

// Light carried through s mm of stone, relative to what the same stone reflects: Cycles' random
// walk through a slab (isotropic scattering, no reflection inside the boundary, dropped after 256
// flights), tabulated by tools/slab_walk_table.py (marble::slabTransportFor) and read here
// linearly in ln T between nodes, 0 beyond the table (tau > 64: under 1e-5 of the reflected light;
// the walk's cap makes it fall faster than any exponential there). Divided by R_inf because the
// albedo multiplies the diffuse light later (post pass). Against Cycles' own slab renders of the
// issue's stone it agrees within their noise at 2-20 mm; the dipole it replaced let 1.3-1.5x too
// much red through (docs/quality.md, "Transmission from a random walk").
// The table's coordinate x for optical thickness tau per channel (nodes at integer x, clamped to
// the table), and the segment of ln(T / R_inf) that holds x: .lo its value at node floor(x), .slope
// its rise per unit of x (ln T is linear in x between nodes).
vec3 slab_x(vec3 tau) { return sqrt(clamp(tau / u_slab_tau_max, 0.0, 1.0)) * float(SLAB_NODES - 1); }
void slab_segment(vec3 x, out vec3 lo, out vec3 slope) {
  ivec3 i = min(ivec3(x), ivec3(SLAB_NODES - 2));
  vec2 r = slab_segment_ends(u_slab_segment_r[i.r]), g = slab_segment_ends(u_slab_segment_g[i.g]),
       b = slab_segment_ends(u_slab_segment_b[i.b]);
  lo = vec3(r.x, g.x, b.x);
  vec3 hi = vec3(r.y, g.y, b.y);
  slope = hi - lo;
  lo -= slope * vec3(i);  // so that ln T = lo + slope * x
}
vec3 slab_transport(float s_mm) {
  vec3 tau = u_slab_sigma_t_mm * s_mm;
  vec3 x = slab_x(tau), lo, slope;
  slab_segment(x, lo, slope);
  return exp(lo + slope * x) * vec3(lessThan(tau, vec3(u_slab_tau_max)));
}

// The translucent shadow map's filter (Dachsbacher & Stamminger 2003): the light leaving at x is
// the sum over the entry points x_j around it, seen in the light's map, of the light entering there
// (E_j = cos_j principled_entry(cos_j) per unit of the light's cross-section, times the
// cross-section A_j the tap stands for) times the stone's response R(|x - x_j|) for that 3D
// distance. R is the one kernel that makes an evenly lit flat slab give the random walk's slab
// transport T(s) (slab_transport): integrating over the entry plane, int R(sqrt(s^2 + rho^2)) 2 pi
// rho drho = T(s) for every s, i.e. R(r) = -T'(r) / (2 pi r), so the share of a ring a <= rho < b
// at depth difference s is T(sqrt(s^2 + a^2)) - T(sqrt(s^2 + b^2)) and the rings telescope to T(s)
// when every tap finds the slab's entry at the same s (the tests TransmissionSlab.*). In a curved
// thin part (a handle, a horn) the taps find entries nearer in 3D than the straight chord on the
// sides, and none beyond the light's silhouette: the walk's shorter paths round the curve (whiter
// light) and the lit area's finite extent (less red, whose kernel is widest). Taps: a centre disc
// of radius S/2 read at the exit's own chord s0 (transmission_thickness: the bilinear entry; on a
// flat slanted entry at the plane's depth, below), and GLOW_RINGS rings with boundaries S/2, S, 2S,
// infinity of GLOW_ANGLES taps each at the ring's area-weighted middle radius (the last at 2.5 S),
// S = max(s0, GLOW_MIN_RADIUS_MM) (the plane's depth p for s0 on a flat slanted entry): the
// kernel's width scales with the chord, so the pattern does too, and it moves continuously with s0.
// Each tap stands for its ring sector at the depth difference it finds (an approximation: constant
// within the sector). Taps whose entry lies beyond the exit (farther from the light) still count at
// their 3D distance. Below GLOW_FROM_MM of chord the straight chord's value is kept, blended to the
// gather by 2 GLOW_FROM_MM: such short chords are the rims of parts, where the taps inward fall on
// the thick side and the gather's light is 0.3 of Cycles' (teapot-back, 0-5 mm chords; the straight
// chord 0.8-0.9 of it). That the rims glow as Cycles' do is measured, not derived: a rim's entries
// lie in a sliver of the light's view, and the kernel gives them little. Measured (docs/quality.md,
// "Eleventh session"): a 10 mm rod's glow 0.88 / 1.01 / 1.00 of a random walk in the rod (the
// straight chord 2.5 / 2.2 / 1.8x); teapot-back's 5-20 mm chords 0.85-1.14 of Cycles' (the straight
// chord 1.24-2.78x). On a slanted flat entry the circles and the disc at s0 were too coarse (a 4 mm
// slab lit at 70 degrees: 0.22 / 0.16 / 0.09 of Cycles'): there the rings lie on the entry's plane
// round the perpendicular's foot instead (slanted_frame). Where the chord is long the outer rings,
// or all, are left out where they add exactly 0 (glow_rings_shared; docs/performance.md, "Twelfth
// session: the gather's rings that add nothing").
const int GLOW_RINGS = 3;
const int GLOW_ANGLES = 8;
const int GLOW_LANE_ANGLES = GLOW_ANGLES / 4;  // each texel of a 2 x 2 quad reads a quarter of a ring
const float GLOW_MIN_RADIUS_MM = 2.0;  // S's floor (and 4 light texels)
const float GLOW_FROM_MM = 3.0;
const float DISC_TAP_RADIUS = 0.35355;  // the centre disc's area-median radius over S: (S / 2) / sqrt(2)

// The thickness the transmission uses: as thickness_at(), but the light's distance map is
// interpolated bilinearly between the four texels around p instead of read at the nearest one.
// Within one texel the true entry distance changes by a texel times the surface's slope seen
// from the light; read nearest, those steps (several texels' worth at grazing light, where the
// inward offset cannot hide them) come out of exp(-sigma_tr s) as speckle on the lit side and as
// jagged edges where the glow fades (seen on the built-in torus at 100 mm per unit). Texels that
// saw nothing are left out (blending in their "nothing hit" distance would invent huge entry
// distances: the reason the map itself is sampled nearest); where none of the four saw the
// object, nothing is in the way and s = 0, as in thickness_at(). Across an edge of the light's
// map the four texels' chords are averaged by the light each lets through, not their entries.
// Also returns, in .y, the cosine at which the light entered there (interpolated with the same
// weights; light_depth.frag.glsl stores it beside the distance). transmission_chord.glsl: the reads.
// For the exit P (normal N) the chord is P_in's (P_in = P - 2 texels N, against acne), read around
// P_in; on a face turned from the light also along P's own light ray (chord_read_point), which is
// taken where P_in's sideways step found a longer chord, a shadow's caster (chord_own_ray_share),
// and there, below GLOW_FROM_MM, spread over the walk's footprint of entries (chord_footprint;
// chord_footprint.glsl says why, what it gains and what it costs).
vec2 transmission_thickness(vec3 P, vec3 N, vec3 P_in) {
  vec2 s_cos = transmission_chord(P_in, P_in);
  vec3 L = light_vector(P);
  float NoL = dot(N, L);
  if (NoL < 0.0) {
    vec3 at = chord_read_point(P, L, NoL);
    vec2 own = transmission_chord(P_in, at);
    float share = chord_own_ray_share(s_cos.x, own.x);
    if (share > 0.0) {
      own.x = chord_footprint(at, light_distance_of(P_in), own.x, u_lit_face_ring_mm / u_mm_per_unit,
                              GLOW_FROM_MM / u_mm_per_unit);
      s_cos = mix(s_cos, own, share);
    }
  }
  return s_cos;
}

// The gather's scale S for a chord s0 (scene units).
float glow_scale(float s0) {
  return max(s0, max(GLOW_MIN_RADIUS_MM / u_mm_per_unit, 4.0 * u_light_texel_world));
}

// The slanted entry (docs/quality.md, "Twelfth session: the slanted slab"). Where the light enters
// the stone's surface at cos0 off its normal, the entry surface, taken as its tangent plane, lies
// at p = s0 cos0 from the exit (s0 the chord along the light): the slab's thickness, the depth
// Cycles' walk crosses (it enters cosine-weighted about the normal whatever the light's slant; its
// render of a 4 mm slab lit at 70 degrees matches cos principled_entry(cos) T(4 mm) within 6 %,
// where T(chord) is 3-13x too dark). The entry depth along the light changes across the light's
// plane with slope g, |g| = tan(theta), so the 3D distance from the exit to the entry at offset u
// in that plane is r^2 = p^2 + |u' - f'|^2, the foot f = -s0 cos0^2 g (the perpendicular's foot
// seen in the light's plane) and ' stretching the component along g by 1 / cos0: the rings of the
// kernel lie on the entry plane around the foot, which the light's plane sees as ellipses shrunk
// by cos0 along g. slanted_frame returns the foot (t1, t2 coordinates) in .xy and the unit
// direction of g in .zw, or zero direction where the map gives none (an entry at normal incidence,
// or the light's silhouette within two texels): then the rings are the light-plane circles round
// the exit, the eleventh session's gather. The magnitude comes from the stored cosine, the
// direction from the entry depth two texels along t1 and t2 (two more entry reads a texel).
// Where the entry is not flat over the foot's reach (a curved part: a rod's tangent plane runs off
// the rod), the plane's depth is not the walk's: slanted_frame also checks the plane at the foot,
// where the light's map must find the entry at 3D distance p from the exit if the plane holds, and
// scales the slant by `planar` (1 within 10 % of p, 0 from 30 %; 0 where the foot sees no entry).
// Measured: without that check the 10 mm rod (TransmissionCurved) read 1.3-1.65x the walk.
// The entry must also be flat: its cosine the same at the secant points and the foot (`bend`),
// or else the exit parallel to it, facing away from the light at the entry's own cosine
// (exit_cos = -N.L at the exit, `parallel`): a curved plate of even thickness (an ear, a leaf),
// whose entry cosine changes across the secants while the walk still crosses its thickness p, not
// the chord (TransmissionShell: a 4 mm plate curved at 46 mm radius, 0.97-1.02 of the slab's law
// at 40-45 degrees; with the flatness check alone 0.72-0.82). `parallel` is no convexity test (a
// circle's chord meets both its ends at one angle): on a rod the secants' slope and the foot's
// distance (`fit`, `miss`), which see the entry bend away from its tangent plane, refuse the plane
// as before (TransmissionCurved reads the same to the digit); without `bend` at all the torus under
// a point light had a seam (1.2x TransmissionSeams' threshold), which `parallel` keeps out.
// Tolerance 0.1-0.3 of the cosines' difference: at 0.05-0.15 the bunny's ears (curved plates, not
// exactly parallel) took half of the gain (docs/quality.md, "Thirteenth session").
vec4 slanted_frame(vec3 P_in, float s0, float cos0, float exit_cos, vec3 t1, vec3 t2, out float planar) {
  float h = max(2.0 * u_light_texel_world, 0.5 * s0 * max(cos0, 0.05));
  vec3 q1 = P_in + h * t1, q2 = P_in + h * t2;
  vec3 e1 = light_entry_at(q1), e2 = light_entry_at(q2);
  vec2 g = vec2(light_distance_of(q1) - e1.x - s0, light_distance_of(q2) - e2.x - s0);
  float c = max(cos0, 0.05);
  float tan_theta = sqrt(max(1.0 - c * c, 0.0)) / c;
  float len = length(g);
  vec2 dir = len > 0.0 ? g / len : vec2(1.0, 0.0);
  vec2 foot = -s0 * c * c * tan_theta * dir;
  vec3 qf = P_in + foot.x * t1 + foot.y * t2;
  vec3 ef = light_entry_at(qf);
  float sf = light_distance_of(qf) - ef.x;
  float p = s0 * c;
  // A plane: the secants' slope is the stored cosine's, the cosine the same at both secant points,
  // and the foot's entry at 3D distance p; each check fades over a range, so planar is continuous.
  float slope = h * tan_theta;
  float fit = abs(len - slope) / max(slope, 1e-6 * h);
  float bend = max(max(abs(e1.y - cos0), abs(e2.y - cos0)), abs(ef.y - cos0));
  float miss = abs(sqrt(dot(foot, foot) + sf * sf) - p) / max(p, 1e-6);
  float flat_entry = 1.0 - smoothstep(0.01, 0.05, bend);
  float parallel = 1.0 - smoothstep(0.1, 0.3, abs(exit_cos - cos0));
  planar = smoothstep(0.9, 1.0, min(min(e1.z, e2.z), ef.z)) * (1.0 - smoothstep(0.05, 0.15, fit)) *
           max(flat_entry, parallel) * (1.0 - smoothstep(0.05, 0.15, miss));
  return vec4(planar * foot, dir);
}

// The depth the straight model and the centre disc cross: the chord s0 tilted toward the entry
// plane's depth s0 cos0 as far as the plane holds (slanted_frame's `planar`).
float slanted_depth(float s0, float cos0, float planar) {
  return s0 * mix(1.0, cos0, planar);
}

// This texel's quarter of the rings: angles k = lane, lane + 4 of each ring (lane: the texel's
// place in its 2 x 2 quad), each tap's share already divided by GLOW_ANGLES, so that the four
// quarters of a quad add up to the whole ring sum of one texel (glow_rings_shared). Only the first
// `rings` rings (glow_rings_shared leaves out the outer ones where they add nothing); the centre
// disc only where the quad `gathers` (its result is blended in nowhere else). The rings lie on the
// entry's plane round the perpendicular's foot (slanted_frame's `frame` and `planar`; p =
// slanted_depth, S = glow_scale(p), t1, t2 the light's plane: all from glow_rings_shared): tap j at
// ring radius rho finds its entry at 3D distance r_j, and counts as the plane's ring at depth d_j =
// sqrt(r_j^2 - rho^2) (= p on a flat slab, so the rings telescope to T(p) there as they do to T(s0)
// at normal incidence). Its weight is the light entering per unit of the light's cross-section,
// principled_entry(cos_j), times the light's cross-section of the plane's ring, cos0 times its area
// (the eleventh session's weight cos_j principled_entry(cos_j) counted the slant twice: a slanted
// slab got cos^2).
vec3 glow_ring_quarter(vec3 P_in, float cos0, float p, float S, vec3 t1, vec3 t2, vec4 frame, float planar,
                       int lane, bool gathers, int rings) {
  const float bounds[4] = float[4](0.5, 1.0, 2.0, 1e6);
  const float radii[3] = float[3](0.7906, 1.5811, 2.5);  // sqrt((a^2 + b^2) / 2), the last 2.5
  // The light-plane circles shrunk by `shrink` along g: a linear map, so the 8 sectors of a ring
  // keep equal areas, and the identity wherever planar = 0, whatever g's direction (a pattern
  // turned with g would jump where g turns: seams on the torus under a point light).
  float shrink = mix(1.0, max(cos0, 0.05), planar);
  mat2 squash = mat2(1.0) - (1.0 - shrink) * outerProduct(frame.zw, frame.zw);
  // The centre disc (radius S / 2 round the foot, at depth p), a quarter of it here: the quad's
  // sharing adds four quarters (or scales what it takes by 4 / quarters taken) as for the rings.
  // A branch the quad takes together (`gathers` is the quad's, glow_rings_shared).
  // The disc is read at the exit's own chord, as if stone filled all of it; where the part seen from
  // the light is narrower than the disc (a flank beside the light's silhouette, a fin, a rim), only
  // the covered share has entries. Each quarter takes its share from one tap of its own at the
  // disc's area-median radius (S / (2 sqrt 2)), at the quarter's diagonal angle: e.z, the share of
  // the light's map there that saw stone (0 beyond the light's silhouette), as the rings' taps
  // count theirs, so the quad's four quarters give the disc times the mean of four taps. Exact
  // where the disc is all stone or all air at each tap's quarter (a rod's or sphere's middle: the
  // taps at 0.71 of the radius fall inside, the same light as before); coarse in between (four
  // taps; docs/quality.md, "Twenty-eighth session: the transmission through the stone").
  float mm = u_mm_per_unit;
  vec3 sum = vec3(0.0);
  if (gathers) {
    float phi = (float(lane) + 0.5) * (0.5 * PI);
    vec2 u = frame.xy + DISC_TAP_RADIUS * S * (squash * vec2(cos(phi), sin(phi)));
    float covered = light_entry_at(P_in + u.x * t1 + u.y * t2).z;
    sum = 0.25 * covered * cos0 * principled_entry(cos0) *
          (slab_transport(p * mm) - slab_transport(sqrt(p * p + 0.25 * S * S) * mm));
  }
  // One loop over the taps, not rings x angles, to the count the quad reads: llvmpipe stops a loop
  // once none of a block's lanes has an iteration left (glow_rings_shared).
  for (int k = 0; k < GLOW_LANE_ANGLES * rings; ++k) {
    int i = k / GLOW_LANE_ANGLES, j = k - i * GLOW_LANE_ANGLES;
    // The ring's bounds and radius by selects, not by indexing the arrays (the same values): the
    // counter differs between lanes to llvmpipe, so an indexed read is a load per lane; the selects
    // took 0.5 M instructions off the dragon's 800^2 frames, pictures byte-equal (docs/performance.md,
    // "Twentieth session: byte-equal savings").
    bool first = i == 0, second = i == 1;
    float a = (first ? bounds[0] : second ? bounds[1] : bounds[2]) * S;
    float b = (first ? bounds[1] : second ? bounds[2] : bounds[3]) * S;
    float rho = (first ? radii[0] : second ? radii[1] : radii[2]) * S;
    {
      float phi = (float(lane + 4 * j) + 0.5 * float(i)) * (2.0 * PI / float(GLOW_ANGLES));
      vec2 u = frame.xy + rho * (squash * vec2(cos(phi), sin(phi)));
      vec3 q = P_in + u.x * t1 + u.y * t2;
      vec3 e = light_entry_at(q);
      float sk = light_distance_of(q) - e.x;
      // d >= 0, so the kernel distances below are >= a: the ring count's bound (glow_rings_shared).
      float d = sqrt(max(dot(u, u) + sk * sk - rho * rho, 0.0));
      vec3 ring = slab_transport(sqrt(d * d + a * a) * mm);
      if (i + 1 < GLOW_RINGS) ring -= slab_transport(sqrt(d * d + b * b) * mm);
      // e.z = 0 where no light enters (a select, not a branch: the quad's texels stay in step).
      sum += (e.z > 0.0 ? e.z * e.y * principled_entry(e.y) / float(GLOW_ANGLES) : 0.0) * max(ring, vec3(0.0));
    }
  }
  return sum;
}

// The other texel of the 2 x 2 quad across x (or y): a fine derivative is the difference between
// the quad's two texels along that axis, so v +- it is the neighbour's value (to rounding).
vec4 quad_across_x(vec4 v) {
  vec4 d = dFdxFine(v);
  return (int(gl_FragCoord.x) & 1) == 0 ? v + d : v - d;
}
vec4 quad_across_y(vec4 v) {
  vec4 d = dFdyFine(v);
  return (int(gl_FragCoord.y) & 1) == 0 ? v + d : v - d;
}

// The gather's rings for the texel at full-resolution pixel px, shared across its 2 x 2 quad:
// each texel reads a quarter of the 24 taps (glow_ring_quarter) and takes the other quarters from
// the quad's texels whose exit lies on its own part of the stone (centres within S / 4 of each
// other, chords within S / 4); quarters it cannot take are made up by scaling what it has
// (4 / the quarters taken), as a gather of fewer angles. The quad's centres are a lighting texel
// (2 pixels) apart, small against S (2 mm and more). A quarter of the taps per texel: the lighting
// pass's cost of the gather about a quarter of the 24-tap one (docs/quality.md, "Eleventh
// session"). Must run in uniform control flow (derivatives): main() calls it before any texel
// returns, and background texels take part with nothing (`stone` false; main() keeps NaNs out of
// their P_in and s_cos with a select). s_cos: transmission_thickness(P, N, P_in), from main(); N the
// exit's normal (slanted_frame's parallel-faces check).
vec3 glow_rings_shared(bool stone, vec3 P_in, vec2 s_cos, vec3 N) {
  float s0 = s_cos.x, cos0 = s_cos.y;
  bool ok = stone && s0 > 0.0;
  float mm = u_mm_per_unit;
  // The quad `gathers` where some texel of it blends the gather in (gathered_transport: from
  // GLOW_FROM_MM of chord on); only there the entry plane is looked for (slanted_frame: three
  // entry reads) and the centre disc read. A branch the quad takes together, so its derivatives
  // stay defined, and llvmpipe, which shades a block's lanes in step, skips it where the whole
  // block is thin or lit.
  vec4 chord = vec4(ok ? s0 : 0.0);
  chord = max(chord, quad_across_x(chord));
  chord = max(chord, quad_across_y(chord));
  bool gathers = chord.x * mm > GLOW_FROM_MM;
  vec3 L = light_vector(P_in);
  vec3 t1 = normalize(cross(L, abs(L.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(L, t1);
  float planar = 0.0;
  vec4 frame = vec4(0.0, 0.0, 1.0, 0.0);
  if (gathers) frame = slanted_frame(P_in, s0, cos0, max(-dot(N, L), 0.0), t1, t2, planar);
  float p = slanted_depth(s0, cos0, planar);
  float S = glow_scale(p);
  // How many rings the quad reads (the quarters must read the same ones). None where the quad
  // does not gather. Nor the rings that add exactly nothing: ring i's taps sit at kernel distances
  // sqrt(d_j^2 + a_i^2) >= a_i (a_i = S/2, S, 2S), whatever the slanted placement: d_j (the
  // plane's depth the tap finds, glow_ring_quarter) is a square root, so >= 0, and a_i is the
  // same a_i = bounds[i] S, S = glow_scale(p) of the slanted depth p <= s0, that the taps use (the
  // shrink and the foot move where a tap reads the entry, not its kernel distance's lower bound).
  // slab_transport is exactly 0 from tau = u_slab_tau_max on, so where a_i sigma_t >= tau_max in
  // every channel each of the ring's terms is max(0 - 0, 0) = 0 and leaving it out changes no
  // bit. The bound must use this S, not glow_scale(s0): on a slanted flat entry p = s0 cos0 and S
  // is smaller, so rings that glow_scale(s0) would leave out still carry light there. A texel
  // needs the rings with a_i sigma_t < tau_max for its own S; the quad reads the most any texel
  // needs. For the default stone (sigma_t >= 2.19 / mm, tau_max 64): the outer ring left out from
  // S = 14.6 mm, the middle one from 29 mm, all from 58 mm -- mostly the thick body's shadowed
  // side, whose long chords pass the first test though nothing crosses them; for the references'
  // principled-white stone, whose light goes farther, from longer chords. The centre disc is no
  // ring: it is read wherever the quad gathers.
  // A count, and the taps in one loop to it: llvmpipe shades a block's lanes in step under a lane
  // mask, and stops the loop once none of them has a tap left, so a block saves the taps all its
  // quads leave out (docs/performance.md, "Twelfth session: the gather's rings that add nothing").
  // No branch: every texel goes on to the exchange below (its derivatives need the quad in step).
  float tau_inner = 0.5 * S * mm * min(u_slab_sigma_t_mm.r, min(u_slab_sigma_t_mm.g, u_slab_sigma_t_mm.b));
  float tau_zero = u_slab_tau_max * 1.0001;  // a margin for the taps' own rounding of a_i sigma_t
  float need = float(tau_inner < tau_zero) + float(2.0 * tau_inner < tau_zero) + float(4.0 * tau_inner < tau_zero);
  vec4 most = ok ? vec4(s0, need, 0.0, 0.0) : vec4(0.0);
  most = max(most, quad_across_x(most));
  most = max(most, quad_across_y(most));
  int rings = most.x * mm <= GLOW_FROM_MM ? 0 : int(most.y + 0.5);
  int lane = (int(gl_FragCoord.x) & 1) + 2 * (int(gl_FragCoord.y) & 1);
  vec3 mine = glow_ring_quarter(P_in, cos0, p, S, t1, t2, frame, planar, lane, gathers, rings);
  bool finite = !any(isnan(mine)) && !any(isinf(mine)) && !any(isnan(P_in)) && !isnan(s0);
  ok = ok && finite;
  vec4 a = ok ? vec4(mine, s0) : vec4(0.0, 0.0, 0.0, -1.0);  // chord -1: nothing to take
  vec4 b = ok ? vec4(P_in, 0.0) : vec4(0.0);
  vec4 ax = quad_across_x(a), bx = quad_across_x(b);
  vec4 ay = quad_across_y(a), by = quad_across_y(b);
  vec4 axy = quad_across_y(ax), bxy = quad_across_y(bx);
  float tol = 0.25 * glow_scale(s0);
  vec3 sum = a.xyz;
  float taken = 1.0;
  vec4 others_a[3] = vec4[3](ax, ay, axy);
  vec4 others_b[3] = vec4[3](bx, by, bxy);
  for (int k = 0; k < 3; ++k) {
    bool take = others_a[k].w > 0.0 && abs(others_a[k].w - s0) <= tol && distance(others_b[k].xyz, P_in) <= tol;
    sum += take ? others_a[k].xyz : vec3(0.0);
    taken += take ? 1.0 : 0.0;
  }
  return ok ? sum * (4.0 / taken) : vec3(0.0);
}

// The gather at the exit P_in (chord s0, entry cosine cos0), its centre disc and rings given
// (glow_rings_shared, glow_ring_quarter). Below GLOW_FROM_MM of chord (rims) the straight model, at
// the chord: there the plane's depth is not checked (slanted_frame runs in the gather's quads only).
vec3 gathered_transport(vec3 P_in, float s0, float cos0, vec3 rings) {
  float mm = u_mm_per_unit;
  vec3 straight = cos0 * principled_entry(cos0) * slab_transport(s0 * mm);
  float blend = smoothstep(GLOW_FROM_MM, 2.0 * GLOW_FROM_MM, s0 * mm);
  if (blend <= 0.0) return straight;  // most of a lit or thin picture
  return mix(straight, rings, blend);
}

// The share of the first bounce entering at the transmission's entry (bounce_entry.glsl) that
// leaves here: the transport the light's own entering light gets (`transport`,
// gathered_transport: the rings' spread over the entries around the chord beyond GLOW_FROM_MM,
// the straight model below it) per unit of light entering at the centre entry, i.e. with the
// light's coupling there, cos_in principled_entry(cos_in), divided out. Until session 23 the
// bounce crossed by the straight model alone, slab_transport at the chord along the light,
// beside the light's rings: on a flat plate 12 mm thick lit at 45 degrees that carried 0.10-0.41
// of the light's own share (tests/bounce_entry_gl_test.cpp; 0.65-0.80 now), too little, and over
// curved parts 5-20 mm thick up to 1.2-2.8x too much (the straight model against the rings there,
// hidden_mirror.glsl, "Eleventh session": teapot-back's spout and shoulder, red where Cycles'
// indirect light is grey). Approximation: the bounce enters over the same ring of entries
// as the light, weighted by the light's cosine at each (it arrives diffusely, from the lit parts
// around, not along the light); exact where the entries' cosines are the centre's (a flat part).
// CROSSED_MIN_COS keeps a grazing centre entry from dividing the rings' steeper entries by a
// vanishing cosine (the ten reference scenes the same to 4 digits with 1e-30 in its place).
// Docs/quality.md, "Twenty-third session: teapot-back".
const float CROSSED_MIN_COS = 0.1;
vec3 crossed_share(float cos_in, vec3 transport) {
  float c = max(cos_in, CROSSED_MIN_COS);
  return transport / (c * principled_entry(c));
}

#include "hidden_mirror.glsl"

// How much the camera sees of `entry` (where the transmitted light entered the stone): 1 where
// it does, 0 where the object hides it, off screen or against the background. The subsurface
// blur spreads the light entering every surface the camera sees over its neighbours, so light
// whose entry the camera sees is, near that entry, already in the picture (docs/quality.md,
// "Tenth session: the back-lit glow"). Two conditions, each a ramp, not a yes/no, so that the
// weight built on it changes smoothly where an entry passes behind a silhouette or a terminator:
// - the surface the camera sees in the entry's direction lies at the entry: within tol (the map's
//   placement of the entry, a few texels), gone from 3 tol (the stone in front of it hides it);
// - that surface faces the light. The light entered through a surface facing it (the map's
//   entry cosine is > 0); a surface the camera sees within tol of the entry but facing away from
//   the light is another sheet -- the far face of a part thinner than tol, the front wall of the
//   teapot's open body where the light enters its inner face through the lid's gap -- and the
//   entry is behind it. Without this, light crossing such a thin part was counted as seen and
//   weighted as the terminator's, away^2 (0.49 on teapot-back's lid rim, docs/quality.md,
//   "Twentieth session: teapot-back's thin sheets"). Ramp over N.L -0.1 ... 0, as the
//   transmission's own turn-on over the exit's N.L (marble_entering): across a terminator the
//   shading normals and the map's cosines disagree by about that much.
float entry_seen(vec3 entry, float tol) {
  vec4 clip = u_view_proj * vec4(entry, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  if (clip.w <= 0.0 || any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 0.0;
  ivec2 size = textureSize(u_depth, 0);
  ivec2 pixel = min(ivec2((ndc.xy * 0.5 + 0.5) * vec2(size)), size - 1);
  vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
  // The pixel's depth and normal through their samplers at its centre (GL_NEAREST: nearest_texel.glsl).
  float depth = textureLod(u_depth, uv, 0.0).r;
  if (depth >= 1.0) return 0.0;
  vec3 S = surface_point(uv, depth);
  float at_entry = 1.0 - smoothstep(tol, 3.0 * tol, distance(S, entry));
  if (at_entry <= 0.0) return 0.0;
  vec3 N_seen = decode_normal(textureLod(u_normal, uv, 0.0).xy);
  return at_entry * smoothstep(-0.1, 0.0, dot(N_seen, light_vector(S)));
}

// The cosine the light entered at, for a chord s (scene units) read at the inward-offset exit P_in:
// the map's (s_cos.y) wherever the read finds stone between P_in and the light, and the exit's own
// max(N.L, 0) where it finds none (s = 0), blended over the first ENTRY_OWN_TEXELS light texels of
// chord so the weight stays continuous. Why: P_in lies 2 texels inside the stone, so a ray from it
// to the light must cross the surface; a read that finds the entry at or behind P_in (s = 0) has
// averaged texels across a silhouette or a grazing surface, or seen an open wall's other side (the
// teapot's body is an open sheet: at the lid's crack its outer side read its own inner side), and
// its cosine belongs to whatever those texels saw. Then the light reaches P through P's own
// surface, at P's own cosine: cos principled_entry(cos) -> 0 as N.L -> 0 (grazing entry through a
// chord -> 0 carries nothing), 0 facing away. teapot-back's crack (x 122-124, rows 82-83): Cycles
// 0.009-0.020, the map's cosine 0.041-0.088, this 0.007-0.026. On a lit plane the offset's chord is
// 2 texels / N.L >= 2 texels, beyond the blend: the lit side is unchanged. Measured (docs/quality.md,
// "Twenty-sixth session: the zero chord's cosine"): ten scenes' mean +0.0006 (teapot-side +0.0043,
// teapot-back +0.0021, none down by more than 0.00012); the blend's width 0.5 texel (0 ... 1 within
// 0.0005 on both teapots; from 1.5 texels on it cuts the rims' real short chords).
const float ENTRY_OWN_TEXELS = 0.5;
float entry_cosine(vec2 s_cos, float NoL) {
  return mix(max(NoL, 0.0), s_cos.y, smoothstep(0.0, ENTRY_OWN_TEXELS * u_light_texel_world, s_cos.x));
}

// The stone between the transmission's inward-offset exit P_in and the exit P itself. The chord s
// is read at P_in (2 light texels inside along -N, against acne), but the walk leaves at P: on the
// side turned from the light P lies farther from the light than P_in by dl = light_distance_of(P) -
// light_distance_of(P_in) (2 texels on a face turned straight away, 0 along the light's silhouette,
// none on the lit side), so the light crosses s + dl of stone. Returned: T(s + dl) / T(s) per
// channel from the slab table's own log slope (the same walk: the slope of the table's segment that
// holds s, exact while s + dl stays in it), which every part of the transport (straight chord,
// rings, the crossed bounce) takes as one factor: exact for the straight chord through a flat
// entry, and for the rings to first order in dl / S (dl <= 2 texels, S >= 4 texels). Along the
// light: on a slab slanted at theta the plane's depth (slanted_depth) grows by the whole 2 texels
// but this adds 2 texels cos theta of chord (the slanted slab's test reads 0.96-1.02 of its
// thickness's law at 0-70 degrees all the same). Before session 27 the transport was read at s
// alone: through TransmissionSlab's 10 mm slab (2 texels 0.34 mm) 1.05 / 1.09 / 1.13x (r / g / b)
// what the walk lets through the whole slab, and in the back-lit statues (2 texels 0.68 mm at 100
// mm per unit) 1.06-1.4x, part of the dark body's surplus over Cycles' direct light (this factor
// 0.71-0.94 there; ten reference scenes' mean SSIM +0.0012, buddha-back +0.0068, dragon-back
// +0.0032: docs/quality.md, "Twenty-seventh session: the transmission's exit"). Where s + dl runs
// past the table the ratio is taken just inside its end (tau clamped to tau_max - dtau), so light
// the rings bring over long chords keeps the table's last slope rather than being cut to 0; a chord
// of 0 (no stone toward the light) is left as it is (entry_cosine: the exit's own surface).
vec3 exit_depth_share(vec3 P, vec3 P_in, float s) {
  vec3 dtau = u_slab_sigma_t_mm * (max(light_distance_of(P) - light_distance_of(P_in), 0.0) * u_mm_per_unit);
  vec3 tau = min(u_slab_sigma_t_mm * (s * u_mm_per_unit), max(vec3(u_slab_tau_max) - dtau, vec3(0.0)));
  vec3 x = slab_x(tau), lo, slope;
  slab_segment(x, lo, slope);
  return s > 0.0 ? min(exp(slope * (slab_x(tau + dtau) - x)), vec3(1.0)) : vec3(1.0);
}

// The `marble` mode, light that enters the stone here (linear HDR, irradiance / PI before the
// albedo): through the surface from the light and the environment, and through the stone from
// the light's far side. What the surface reflects is added by the post pass
// (marble_reflected), so changing only the gloss re-runs neither this pass nor the blur.
// P_in and s_cos: the transmission's exit and transmission_thickness(P, N, P_in), computed once in main()
// for this and glow_rings_shared. bounce: light bounced off the object's other lit parts
// (marble_bounce, bounce.glsl, gathered by the bounce pass), computed in main(), which also lends it
// to the hidden mirror's face (hidden_mirror.glsl).
vec3 marble_entering(vec3 P, vec3 N, vec3 L, vec3 P_in, vec2 s_cos, vec3 glow_rings, vec3 bounce) {
  float NoL = dot(N, L);
  vec3 E = light_irradiance(light_distance_of(P));
  float visible = receiver_plane_visibility(P, N, u_light_texel_world);
  vec3 entering = marble_surface_entering(N, L, E, visible, u_env_intensity) + bounce;

  // Transmission: light that entered where the light's map says, at the cosine stored there and
  // with the Principled coupling (as the direct light), and crossed s millimetres of stone to leave
  // here, carried by the random walk's slab transport (slab_transport). An inward offset keeps the
  // surface's own depth sample out (no acne): P_in = P - N * (2 u_light_texel_world) (main()).
  // It reaches the side facing away from the light; facing the light, the direct term
  // already carries that light (weight after Barre-Brisebois & Bouchard 2011). That weight,
  // (1/2 - N.L/2)^2, is 1/4 where the light grazes, so it also dimmed the rims of thin parts seen
  // against the light, where the chord is shortest and Cycles' glow brightest. Facing away, the
  // slab's transport does not depend on the exit's orientation, so the weight is 1 there unless
  // the camera sees where the light entered: then the subsurface blur already spreads that
  // entry's light across the terminator, and the weight keeps it from being counted twice.
  // The light's falloff is taken where it entered, s before the (offset) exit point.
  // The entry is principled_entry, Cycles' coupling for light entering the walk, since session 8;
  // before, the Fresnel transmittance 1 - F(cos), because with the dipole's transport the
  // Principled one, falling only linearly at grazing entry, left a faint seam on the torus's
  // grazing-lit top (1.1x the threshold of tests/transmission_seams_gl_test.cpp); with the random
  // walk's transport the worst there is 0.74 of it, and against Cycles it raises SSIM in all ten
  // reference scenes (by up to 0.006; docs/quality.md, "Transmission from a random walk").
  float s = s_cos.x;
  float cos_in = entry_cosine(s_cos, NoL);
  float away = clamp(0.5 - 0.5 * NoL, 0.0, 1.0);
  float weight = away * away;
  vec3 transport = gathered_transport(P_in, s, cos_in, glow_rings);
  vec3 crossed = vec3(0.0);
  if (NoL < 0.0 && s > 0.0) {
    // Only here: P lies farther from the light than P_in only where N faces away from it (N.L < 0),
    // and with no chord there is no stone to add (exit_depth_share is 1 elsewhere).
    transport *= exit_depth_share(P, P_in, s);
    // The entry, s back toward the light along its ray, is where the light's map puts it to within
    // the inward offset and the map's interpolation (a few texels): hidden from 4 texels on, fully
    // from 12, or where the surface the camera sees there faces away from the light (entry_seen).
    // Turned on over the first 0.1 of -N.L so that the weight stays continuous there.
    float tol = 4.0 * u_light_texel_world;
    float hidden = (1.0 - entry_seen(P_in + light_vector(P_in) * s, tol)) * (1.0 - smoothstep(-0.1, 0.0, NoL));
    weight = mix(weight, 1.0, hidden);
    // The first bounce entering at the same entry (bounce_entry.glsl), carried through the chord
    // by the same transport as the light's own (crossed_share). Only where the camera does not
    // see the entry: where it does, the camera-side gather already holds that light
    // (marble_bounce) and the blur spreads it.
    crossed = bounce_entering_at(P_in) * crossed_share(cos_in, transport) * hidden;
  }
  return entering + (light_irradiance(light_distance_of(P_in) - s) / PI * transport * weight +
                     u_light_radiance * crossed) * u_translucency;
}

// The paper's reflectance (§3.3) on colour C: the Schlick term F over it, by schlick_blend.
vec3 paper_reflectance(vec3 C, vec3 N, vec3 V, vec3 L) {
  vec3 F = paper_schlick(C, u_metalness, N, V, L, u_schlick_hn);
  return u_schlick_program == 1 ? C - u_k_schlick * (1.0 - F) : mix(C, F, u_k_schlick);
}

void main() {
  o_diffuse = vec4(0.0);
  if (u_mode == MODE_LIGHT_DEPTH) {
    // The light's distance map itself, near = black, far (nothing hit) = white.
    float d = texture(u_light_distance, v_uv).r;
    float t = clamp((d - u_light_near_far.x) / (u_light_near_far.y - u_light_near_far.x), 0.0, 1.0);
    o_color = vec4(vec3(t), 1.0);
    return;
  }
  float depth;  // px's, through the sampler (GL_NEAREST: nearest_texel.glsl)
  ivec2 px = blur_texel_pixel(u_depth, ivec2(gl_FragCoord.xy), u_scale, depth);
  vec2 uv = (vec2(px) + 0.5) / vec2(textureSize(u_depth, 0));  // its centre
  bool stone = depth < 1.0;
  // The surface point, normal and (marble) the transmission's exit and chord, once for the gather
  // and marble_entering; background texels get a point at mid depth (a select: no NaNs into the
  // quad's shared values).
  vec3 P = surface_point(uv, stone ? depth : 0.5);
  vec3 N = decode_normal(textureLod(u_normal, uv, 0.0).xy);
  vec3 P_in = vec3(0.0);
  vec2 s_cos = vec2(0.0);
  vec3 glow_rings = vec3(0.0);
  if (u_mode == MODE_MARBLE) {
    P_in = P - N * (2.0 * u_light_texel_world);
    s_cos = transmission_thickness(P, N, P_in);
    // Before any texel returns: the quad shares it (derivatives need all four in step).
    glow_rings = glow_rings_shared(stone, P_in, s_cos, N);
  }
  // The mirror ray: on screen (self_reflection.glsl; the post pass adds the light there), else
  // against the light's layers (hidden_mirror.glsl; its light added here), shared by the quad, so
  // before any texel returns.
  ivec2 hit = ivec2(-1);
  float hit_t = 0.0;
  vec4 hidden = vec4(0.0);
  if (u_mode == MODE_MARBLE) {
    vec3 V = normalize(u_camera_pos - P);
    if (stone) hit = self_reflection_hit(px, depth, P, N, V, mirror_march_phase(ivec2(gl_FragCoord.xy)), hit_t);
    // Only a ray that comes nearer the light can cross an exit face from behind it: the distance
    // to a point light along a ray is convex in t (along a directional light's travel, linear), so
    // where it grows at P (R.L <= 0) it grows all the way, and the march is skipped, exactly.
    vec3 R = reflect(-V, N);
    hidden = hidden_mirror_shared(stone, stone && hit.x < 0 && dot(R, light_vector(P)) > 0.0, P, R);
    // Where the ray passed behind the visible face it hit into a lit face the camera cannot see, that
    // face's light instead (hidden_mirror.glsl, hidden_lit_face_behind).
    vec4 lit = hidden_lit_face_behind(hit, hit_t, P, R);
    if (lit.a > 0.0) {
      hidden = lit;
      hit = ivec2(-1);
    }
  }
  if (!stone) {
    // No surface: zero light (the linear HDR image and --hdr keep 0 there); the post pass
    // paints the background colour.
    o_color = vec4(0.0);
    return;
  }
  vec3 albedo = nearest_texel(u_albedo, px).rgb;  // GL_NEAREST, px on screen (nearest_texel.glsl)
  vec3 V = normalize(u_camera_pos - P);
  vec3 L = light_vector(P);

  vec3 c;
  if (u_mode == MODE_MARBLE) {
    // Alpha: the view depth, which tells the blur's taps on this surface from others (0, the
    // cleared background, is no stone).
    // Where the mirror ray met a surface, on screen or hidden, the bounce's mirrored part is left
    // out (no light mirrored twice), and so is the environment's reflection (o_mirror_hit -2: a
    // hidden surface, for the post pass).
    if (hit.x >= 0) hidden = vec4(0.0);
    bool escaped = hit == SELF_REFLECTION_ESCAPED;
    o_mirror_hit = vec4(hidden.a > 0.0 ? vec2(-2.0) : escaped ? vec2(-1.0) : vec2(hit), 0.0, 0.0);
    // The bounce's mirrored part only where the mirror ray meets no surface, on screen (the post
    // pass mirrors that one) or hidden; where the ray escaped through the space the camera sees
    // empty (self_reflection.glsl), only the lobe's tail, which alone reaches the lit parts.
    bool mirrorsSurface = hit.x >= 0 || hidden.a > 0.0;
    vec3 bounce = marble_bounce(P, N, px, mirrorsSurface ? 0.0 : escaped ? SELF_REFLECTION_ESCAPED_TAIL : 1.0);
    // The hidden face's light: its glow (hidden.rgb) and its own indirect light, taken as P's
    // diffuse bounce (hidden_mirror.glsl, "the face's indirect light"); without its mirrored part
    // wherever hidden.a > 0, so `bounce` is that diffuse part there.
    vec3 mirrored = fresnel_dielectric(max(dot(N, V), 0.0), u_ior) * (hidden.a > 0.0 ? hidden.rgb + bounce : vec3(0.0));
    o_diffuse = vec4(marble_entering(P, N, L, P_in, s_cos, glow_rings, bounce) + mirrored,
                     linear_depth(depth, u_camera_near_far));
    return;
  } else if (u_mode == MODE_PAPER) {
    vec3 sss = paper_subsurface(u_sigma_t * thickness_at(P), u_k_sss) * u_light_radiance;
    if (u_reflectance_first == 0) {
      // Paper §4: subsurface first, its result is the Schlick input colour.
      c = paper_reflectance(albedo * sss, N, V, L);
    } else {
      c = paper_reflectance(albedo, N, V, L) * sss;
    }
  } else if (u_mode == MODE_PHONG) {
    c = phong(albedo, N, V, L, u_light_radiance, u_shininess);
  } else if (u_mode == MODE_OREN_NAYAR) {
    c = oren_nayar(albedo, N, V, L, u_light_radiance, u_oren_nayar_sigma);
  } else if (u_mode == MODE_SUBSURFACE) {
    c = albedo * paper_subsurface(u_sigma_t * thickness_at(P), u_k_sss);
  } else if (u_mode == MODE_REFLECTANCE) {
    c = paper_schlick(albedo, u_metalness, N, V, L, u_schlick_hn);
  } else if (u_mode == MODE_ALBEDO) {
    c = albedo;
  } else if (u_mode == MODE_THICKNESS) {
    // 0 = black; 2*sqrt(3) scene units (the longest chord of the normalized mesh's
    // bounding sphere, kThicknessViewRange) = white.
    c = vec3(thickness_at(P) / 3.4641016);
  } else if (u_mode == MODE_DEPTH) {
    float dist = distance(P, u_camera_pos);
    c = vec3(clamp((dist - u_camera_near_far.x) / (u_camera_near_far.y - u_camera_near_far.x), 0.0, 1.0));
  } else if (u_mode == MODE_POSITION) {
    c = clamp(P * 0.5 + 0.5, 0.0, 1.0);
  } else {
    c = N * 0.5 + 0.5;
  }
  o_color = vec4(c, 1.0);
}
