// The `marble` mode's one bounce: light that entered the stone where the light hits it,
// re-emerged and falls on another part of the same object (a crease, the inside of a coil).
// Reflective shadow maps (Dachsbacher & Stamminger 2005): the light-depth pass's map holds, per
// texel of the light's view, the lit surface's position, normal and w = area x cos x entry
// (light_depth.frag.glsl); each texel is a small Lambertian emitter of flux
// Phi = albedo x E(d) x w, and the irradiance it gives a point x with normal n is
//   Phi cos_p cos_x / (pi (r^2 + A / pi)),
// the point-emitter law (D&S 2005, eq. 1, with Lambert's 1/pi) with r^2 raised by the emitter's
// area A over pi: the on-axis form of a Lambertian disk of area A (E = pi L a^2 / (r^2 + a^2)),
// so a crease's near side tends to the emitter's radiosity instead of the point law's
// singularity. Since session 9 each texel is also a glossy emitter: the light its surface
// reflects, flux E(d) x area x cos x F(cos) (Schlick; the stone's F0), sent around the mirror
// direction (bounce_sample: the lobe and its error). Since session 10 the receiver is glossy too:
// the camera sees the lit parts mirrored in the stone's surface (light -> emitter -> the
// receiver's specular layer -> camera), which a diffuse receiver leaves out and which is most of
// what back-lit stone shows between its lit rims (docs/quality.md, "Tenth session"; bounce_sample).
// Approximations, each stated:
// - no visibility between emitter and receiver (RSM's own): light can bounce through the stone
//   between two parts that cannot see each other; the cosines already drop every emitter behind
//   the receiver's tangent plane and every receiver behind the emitter's, so a convex surface
//   receives none. Since session 22 the camera-side gathers (which define BOUNCE_SCREEN_OCCLUSION
//   and include bounce_screen_occlusion.glsl first) drop a sample whose way runs into stone next to
//   the receiver, one point tested against the camera's depth buffer, and since session 23 a receiver in another
//   part's light shadow (since session 28 also one on a part thick along the light) takes no sample
//   whose way crosses that part's stone (bounce_through_stone.glsl);
// - the emitter's albedo is the stone's base colour (u_pat_base_color, applied by the lighting
//   pass: bounce_upsample.glsl), not the pattern at the emitter: the veins vary at the millimetre scale the bounce averages over;
// - one bounce from the light's map; the further bounces (from stone lit by this one, which the
//   map cannot hold) come from a radiosity over the whole surface (further_radiosity.h), added by
//   the merge (bounce_merge.glsl);
// - a fixed pattern over a disk of BOUNCE_RADIUS (of the light map's width) around the point's
//   projection in the light's view: a centre sample for the innermost disk (one texel of the map:
//   BOUNCE_RINGS) and BOUNCE_RINGS rings,
//   each twice the radius of the one inside it, of BOUNCE_ANGLES samples at even angles (each ring
//   turned 0.382 of a step from the last), each sample standing for its ring sector (read
//   BOUNCE_LOD_FINER levels finer than the level of the sector's size, since session 9): the disk
//   is covered without gaps, finely near the point (where the emitters that matter most are; D&S
//   2005 also sample densest there) and coarsely far away. The pattern is turned by a quarter of
//   its angular step from one gather texel to the next in each 2 x 2 block (interleaved sampling,
//   Keller & Heidrich 2001; since session 11: bounce_gather's `turn`), and each texel is evened
//   out over its 3 x 3 neighbours on the same surface, a tent that weighs the four turns equally
//   (since session 21: bounce_deinterleave.frag.glsl), so every texel averages four turns of the
//   pattern: its error, a fixed pattern that moves with the light, shrinks where the four agree.
// Gathered by the bounce pass (bounce_gather.frag.glsl) at one texel per 4 x 4 of the lighting
// pass's and brought to them by bounce_upsample.glsl.
// Needs from the includer: deferred_common.glsl (light_falloff, light_vector, light_distance_of,
// u_light_view_proj), rotation.glsl and PI.

layout(binding = UNIT_LIGHTING_BOUNCE_POSITION) uniform sampler2D u_bounce_position;
layout(binding = UNIT_LIGHTING_BOUNCE_NORMAL) uniform sampler2D u_bounce_normal;
#include "bounce_through_stone.glsl"

// Six rings: the innermost disk's radius (BOUNCE_RADIUS / 2^BOUNCE_RINGS = 1/128 of the map's
// width) is one texel of the map's finest level (LightDepthPass: 1024 / 8 = 128 texels across).
// Its one sample reads the receiver's own surface, which sends it nothing, so whatever lies inside
// that disk is lost: with four rings (before session 12) its radius was 4 texels, and the
// emitters just beside a crease's fold (the wall's near strip of the corner, a coil's neighbour)
// were left out: the dragon's bounce was 0.65 of Cycles' first bounce, 0.82 with six
// (docs/quality.md, "Twelfth session: the front- and side-lit scenes"). Below a texel the map
// holds nothing finer to read.
const int BOUNCE_RINGS = 6;
const int BOUNCE_ANGLES = 8;
// From this ring out (4 and 5: 16-64 texels from the receiver) each sector is read at two radii
// (bounce_sample_pair). Pairing rings 0-3 too gained nothing that held over the pattern's phases and
// lost dragon-side 0.0058 (docs/quality.md, "Twenty-seventh session: the gather's rings read at two
// radii").
const int BOUNCE_PAIR_FROM_RING = 4;
const float BOUNCE_RADIUS = 0.5;  // of the light map's width (its uv)
// Rings 0 to BOUNCE_STRATIFIED_RINGS - 1 (1-8 texels from the receiver) are read at one of four radii
// per texel of a 2 x 2 block (bounce_gather's `stratum`, bounce_radial_stratum.glsl), the rest at the
// sectors' middle (ring 3) or in pairs (rings 4, 5). Ring 3 stratified too lost teapot-back 0.0019 of
// SSIM over four phases of the pattern, its handle's inner side and the body beside the lid, already
// darker than Cycles', darker still (docs/quality.md, "Twenty-ninth session: the inner rings' radius
// stratified over the 2 x 2 block"; s27-bounce2 found the same ring read coarser lose the same blocks).
const int BOUNCE_STRATIFIED_RINGS = 3;
// Each sample is read BOUNCE_LOD_FINER mipmap levels finer than the level whose texel is its whole
// sector (8^2 = 64 times fewer texels averaged): a surface point near the sector's middle stands
// for the sector, rather than the mean position and normal over it, which mixes parts at different
// depths wherever the light's view has an edge (a coil in front of another: their mean lies between
// them, in the air or inside the stone, and faces neither). Measured against Cycles (docs/quality.md,
// session 9; with the glossy emitters): dragon-back SSIM 0.529 -> 0.623, the body's grey
// interreflection appears; bunny-side -0.026 (its front paws take light through the chest: no
// visibility).
const float BOUNCE_LOD_FINER = 3.0;

// The glossy emitters' lobe: the light a sample reflects off its surface (Fresnel F of the entry
// cosine, its weight a beside the normal: light_depth.frag.glsl) leaves around the mirror direction
// of the sample's mean normal as a normalized Phong lobe (m + 1) / (2 PI) cos^m, m = BOUNCE_GLOSS.
// Far wider than the stone's own GGX lobe (roughness 0.15: a few degrees): 49 samples over half the
// light's map cannot resolve a sharp lobe, and across one sample (up to a quarter of the map) the
// curved stone's normals spread the reflection over tens of degrees anyway. The flux is right
// (Schlick's F, Cycles' Principled specular with Specular = F0 / 0.08), its direction smeared.
const float BOUNCE_GLOSS = 4.0;

// The glossy receiver (session 10): the emitters' diffuse radiance reflected toward the camera by
// the receiver's specular layer, a normalized Phong lobe (m + 1) / (2 PI) cos^m of exponent
// BOUNCE_MIRROR_GLOSS around the mirror direction R of the view at P (as f cos: its integral over
// the sphere is 1, so the layer reflects F of an even surround, F Schlick's at the view's cosine,
// applied by bounce_upsample.glsl). Cycles' lobe is GGX at alpha = roughness^2 = 0.0225 (the
// reference stone): 1.6 % of its energy lies more than 20 degrees from R and 0.4 % more than 40
// (the GGX half-vector distribution's cumulative tan^2 / (alpha^2 + tan^2), the reflected angle
// twice the half vector's). The 49 samples cannot resolve that, so the lobe is wider, but since
// session 25 not as wide as the emitters' (m = 4 until then: 73 % of the lobe beyond 20 degrees,
// 26 % beyond 40, where Cycles' mirror sees only the stone's own black surround): m = 16 puts
// 35 % beyond 20 degrees and 1.1 % beyond 40, a lobe of about 14 degrees (1 / sqrt(m) radians),
// still wider than one outer ring's sector seen from P. Measured against Cycles (docs/quality.md,
// "Twenty-fifth session"): the ten reference scenes' mean SSIM 0.93908 -> 0.93923 (m = 8: 0.93916,
// m = 24: 0.93923 with bunny-back -0.0004, m = 32: 0.93920); on dragon-back, where the mirror ray
// meets nothing else, the mirrored part falls from 1.99 to 0.94 of Cycles' glossy indirect light.
// (Session 10's m = 16 measured worse, buddha-front relative RMSE 0.174 -> 0.192, on a first
// version with the mirrored part PI too strong and before the marches took the lobe's core.)
// Rougher stones would want a wider lobe: the gather reads no material parameter, so this holds
// the reference stone's. The emitters' own glossy light is not mirrored again (a few percent of
// theirs), and the receiver's lobe is not shadowed or masked (Smith's term for GGX at alpha
// 0.0225 takes under 2 % off up to 85 degrees). Where the view's mirror ray escapes through space
// the camera sees empty (self_reflection.glsl, since session 26), the lighting pass keeps only
// SELF_REFLECTION_ESCAPED_TAIL of this part: GGX's share beyond the core that the ray itself sees.
const float BOUNCE_MIRROR_GLOSS = 16.0;  // bounce_sample raises cosines to it by four squarings

// The mipmap level a sample standing for `texels` of the map's finest level is read at:
// BOUNCE_LOD_FINER levels finer than the level of that area. Per ring, not per sample: the ring's
// samples share their area (a log2 less per sample: -0.9 M instructions of the dragon's 800²
// camera frame, docs/performance.md "Twentieth session: the bounce's grids").
float bounce_sample_lod(float texels, float maxLod) { return clamp(0.5 * log2(texels) - BOUNCE_LOD_FINER, 0.0, maxLod); }

// Irradiance at P (normal N) from the emitters in the area of `texels` of the map's finest level
// around uv, per unit of the light's radiance and before the emitters' albedo and Fresnel factor:
// x, diffuse (times the albedo later); y, z, glossy (times F0 and 1 - F0 later: Schlick's
// F0 + (1 - F0)(1 - cos)^5 split by what depends on the material); w, the radiance P's specular
// layer reflects toward the camera (R: the view's mirror direction at P) of the emitters' diffuse
// light, before the emitters' albedo and P's Fresnel factor.
// The emitter a sample read: pw, the mean of (position x w, w) over the texels it stands for; na,
// the mean of (normal, a). Its callers (bounce_sample, bounce_sample_pair) read them at level
// `lod` (bounce_sample_lod; bilinear within the level: continuous in uv).
vec4 bounce_from_emitter(vec3 P, vec3 N, vec3 R, vec4 pw, vec4 na, float texels, BounceStoneReceiver stone) {
  if (pw.w <= 0.0) return vec4(0.0);
  vec3 xp = pw.xyz / pw.w;
  vec3 np = na.xyz;
  float nl = length(np);
  if (nl < 1e-4) return vec4(0.0);
  np /= nl;
  float A = pw.w * texels;  // the w the sample stands for
  float Aa = na.w * texels;  // and the a
  vec3 d = P - xp;
  float r2 = max(dot(d, d), 1e-12);
  float cosP = dot(np, d);  // x |d|
  float cosX = -dot(N, d);  // x |d|
  if (cosP <= 0.0 || cosX <= 0.0) return vec4(0.0);
#ifdef BOUNCE_SCREEN_OCCLUSION
  // The camera-side gathers: no light whose way runs into the stone next to the receiver
  // (bounce_screen_occlusion.glsl); after the cosines, so only samples that would bring light test it.
  if (bounce_occluded_near_receiver(P, xp)) return vec4(0.0);
#endif
  // A receiver in another part's shadow or on a thick part: no light through that part's stone
  // (bounce_through_stone.glsl).
  if (stone.tested && bounce_crosses_stone(P, stone, xp)) return vec4(0.0);
  float falloff = light_falloff(light_distance_of(xp));
  float diffuse = A * cosP * cosX / (r2 * (PI * r2 + A));
  // Glossy: flux (A + Aa / 2) F0 + Aa (1 - F0) (area x cos = w + a / 2) into the lobe around the
  // mirror direction of the light's direction at xp, with the same softened distance law.
  vec3 mirror = reflect(-light_vector(xp), np);
  float cosR = max(dot(mirror, d), 0.0) * inversesqrt(r2);
  float lobe = (BOUNCE_GLOSS + 1.0) / (2.0 * PI) * pow(cosR, BOUNCE_GLOSS);
  float glossy = lobe * cosX * inversesqrt(r2) / (r2 + A / PI);
  // Mirrored: the emitter's radiance albedo x E x w / (PI area) over its solid angle area cos_p / r^2
  // (softened as the diffuse law), times the receiver's lobe toward it: the area cancels.
  float cosM = max(-dot(R, d), 0.0) * inversesqrt(r2);
  // cos^BOUNCE_MIRROR_GLOSS by four squarings: pow() with the constant 16 cost 1.4 M instructions
  // more of the dragon's 800^2 frame on llvmpipe than pow(x, 4), which it turns into products.
  float cosM2 = cosM * cosM, cosM4 = cosM2 * cosM2, cosM8 = cosM4 * cosM4;
  float mirrored = A * cosP * inversesqrt(r2) / (PI * r2 + A) * (BOUNCE_MIRROR_GLOSS + 1.0) / (2.0 * PI) *
                   (cosM8 * cosM8);
  return falloff * vec4(diffuse, glossy * (A + 0.5 * Aa), glossy * Aa, mirrored);
}

vec4 bounce_sample(vec3 P, vec3 N, vec3 R, vec2 uv, float texels, float lod, BounceStoneReceiver stone) {
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec4(0.0);  // off the map: no light
  return bounce_from_emitter(P, N, R, textureLod(u_bounce_position, uv, lod), textureLod(u_bounce_normal, uv, lod),
                             texels, stone);
}

// The outer rings' samples (bounce_gather, from BOUNCE_PAIR_FROM_RING on): the same sector read at two
// radii, uv -+ duv (a quarter of the ring's inner radius along the sample's direction: 1.25 r0 and
// 1.75 r0, the middles of the sector's inner and outer halves), and the two reads averaged. Read at
// one radius (1.5 r0) a ring found an emitter only near that radius: across buddha-side's robe the
// first bounce striped 0.5-2x Cycles' with the ring's distance, and four radii a ring (four times the
// samples, +213 M instructions of the dragon's 800^2 camera frame) took the mean SSIM of the ten
// reference scenes +0.0027 (docs/quality.md, "Twenty-seventh session: why the first bounce is
// misplaced"). The pair is averaged only where its two points differ mainly across the light's
// direction (one surface seen from the light, `along` at most twice `side`); where they differ mainly
// along it they straddle a depth edge of the light's view (a part and the body behind it), whose mean
// would be a point on neither, and the inner read alone stands for the sector. A read that saw
// nothing (w = 0) averages in as nothing: the sector half empty.
vec4 bounce_sample_pair(vec3 P, vec3 N, vec3 R, vec2 uv, vec2 duv, float texels, float lod, BounceStoneReceiver stone) {
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec4(0.0);  // off the map: no light
  vec4 pw = textureLod(u_bounce_position, uv - duv, lod), pw2 = textureLod(u_bounce_position, uv + duv, lod);
  vec4 na = textureLod(u_bounce_normal, uv - duv, lod), na2 = textureLod(u_bounce_normal, uv + duv, lod);
  bool average = true;
  if (pw.w > 0.0 && pw2.w > 0.0) {
    vec3 g = pw2.xyz / pw2.w - pw.xyz / pw.w;
    vec3 Lg = light_vector(pw.xyz / pw.w);
    float along = abs(dot(g, Lg));
    average = along <= 2.0 * length(g - dot(g, Lg) * Lg);
  }
  if (average) {
    pw = 0.5 * (pw + pw2);
    na = 0.5 * (na + na2);
  }
  return bounce_from_emitter(P, N, R, pw, na, texels, stone);
}

// Irradiance / PI that one bounce brings to P (normal N), per unit of the light's radiance,
// the pattern turned by `turn` of its angular step (bounce_gather.frag.glsl) and the inner rings read at
// the radius of their equal-area stratum `stratum` (0 ... 1; bounce_radial_stratum.glsl), or at their
// middle where `stratum` is BOUNCE_RADIAL_MIDDLE (< 0),
// before P's own albedo and entry, and before the emitters' albedo (x) and Fresnel factors (y, z)
// (bounce_merge.frag.glsl applies those: the gather then reads no material parameter, and a colour
// or ior change re-runs only the bounce pass's last draw and the lighting); w, the radiance P's specular layer mirrors toward
// the camera at V, before the emitters' albedo and P's Fresnel factor.
vec4 bounce_gather(vec3 P, vec3 N, vec3 V, float turn, float stratum) {
  vec3 R = reflect(-V, N);
  vec4 clip = u_light_view_proj * vec4(P, 1.0);
  vec2 centre = clip.xy / clip.w * 0.5 + 0.5;
  float size = float(textureSize(u_bounce_position, 0).x);
  float maxLod = log2(size);
  vec4 sum = vec4(0.0);
  float inner = BOUNCE_RADIUS * exp2(-float(BOUNCE_RINGS));  // the centre sample's disk
  float centreTexels = PI * inner * inner * size * size;
  BounceStoneReceiver stone = bounce_stone_receiver(P, clip);  // once per receiver (bounce_through_stone.glsl)
  sum += bounce_sample(P, N, R, centre, centreTexels, bounce_sample_lod(centreTexels, maxLod), stone);
  // Sample k of ring `ring` at angle 2 PI (k + turn + 0.381966 (ring + 1 + 4 - BOUNCE_RINGS)) /
  // BOUNCE_ANGLES: each ring turned 0.381966 of a step from the one inside it, counted so that the
  // outer four rings keep the angles they had when there were four (session 11): the new inner two
  // add to the pattern without moving the rest, whose turn alone moves the scores (bounce_gather).
  // The angles by rotation (rotation.glsl).
  const float step = 2.0 * PI / float(BOUNCE_ANGLES);
  const vec2 byStep = vec2(cos(step), sin(step)), byRing = vec2(cos(0.381966 * step), sin(0.381966 * step));
  float phi0 = step * (turn + 0.381966 * float(1 + 4 - BOUNCE_RINGS));
  vec2 ringDir = vec2(cos(phi0), sin(phi0));
  for (int ring = 0; ring < BOUNCE_PAIR_FROM_RING; ++ring) {
    float r0 = inner * exp2(float(ring)), r1 = 2.0 * r0;
    // The sectors' middle, or the radius inside which the fraction u of the ring's area lies,
    // r0 sqrt(1 + 3 u), u the texel's stratum moved on by the golden ratio's fraction per ring
    // (bounce_radial_stratum.glsl): over the four strata an even cover of the ring's area, where each
    // sample stands for its sector's area.
    float u = fract(stratum + 0.618034 * float(ring));
    float r = stratum < 0.0 || ring >= BOUNCE_STRATIFIED_RINGS ? 0.5 * (r0 + r1) : r0 * sqrt(1.0 + 3.0 * u);
    float dA = PI * (r1 * r1 - r0 * r0) / float(BOUNCE_ANGLES);
    float texels = dA * size * size, lod = bounce_sample_lod(texels, maxLod);
    vec2 dir = ringDir;
    ringDir = rotate2(ringDir, byRing);
    for (int k = 0; k < BOUNCE_ANGLES; ++k) {
      sum += bounce_sample(P, N, R, centre + r * dir, texels, lod, stone);
      dir = rotate2(dir, byStep);
    }
  }
  // The outer rings read each sector at two radii (bounce_sample_pair), in a loop of their own: in
  // the loop above, a branch choosing the pair made every sample pay for it on llvmpipe (which runs
  // both sides of a branch any lane takes): the camera frame +29 M against +10.9 M so.
  for (int ring = BOUNCE_PAIR_FROM_RING; ring < BOUNCE_RINGS; ++ring) {
    float r0 = inner * exp2(float(ring)), r1 = 2.0 * r0;
    float r = 0.5 * (r0 + r1);
    float dA = PI * (r1 * r1 - r0 * r0) / float(BOUNCE_ANGLES);
    float texels = dA * size * size, lod = bounce_sample_lod(texels, maxLod);
    vec2 dir = ringDir;
    ringDir = rotate2(ringDir, byRing);
    for (int k = 0; k < BOUNCE_ANGLES; ++k) {
      sum += bounce_sample_pair(P, N, R, centre + r * dir, 0.25 * r0 * dir, texels, lod, stone);
      dir = rotate2(dir, byStep);
    }
  }
  // Radiosity albedo x E x w / A leaves the emitters; the receiver takes it in as diffuse light
  // (the environment's 41/42, marble_light.glsl) and the pass stores irradiance / PI. The mirrored
  // part is a radiance already (light_falloff holds E = PI x the light's radiance).
  return vec4(sum.xyz * (41.0 / 42.0) / PI, sum.w);
}
