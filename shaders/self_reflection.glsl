// The stone's own light mirrored in its surface (`marble` mode): what the camera sees in the
// near-mirror specular layer where it reflects another part of the object that the camera also
// sees -- the glowing handle of a back-lit teapot in the body beside it, a lit coil in the crease
// next to it. Cycles' glossy indirect light (its specular layer's view of the object's diffuse and
// transmitted light): 1 % of teapot-back's light and 0.4 % of bunny-back's, but thin bright lines
// along dark edges, where SSIM weighs them (docs/quality.md, "Eighteenth session"). The bounce's
// mirrored part (bounce.glsl) carries light from the light's map only (surfaces the light hits,
// through a wide Phong lobe); this carries whatever the camera sees lit -- transmission, the
// bounces, the lit side -- through the stone's sharp lobe. The lighting pass marches the ray once
// per entering texel (half the resolution by default) and writes where it meets the object
// (o_mirror_hit); the post pass adds F x the blurred light there (post.frag.glsl, mirror_hit_at),
// and the lighting pass keeps the bounce's mirrored part only where the ray meets nothing on
// screen (bounce_upsample.glsl), so no light is mirrored twice -- and where the ray escaped (below)
// only the lobe's tail. Marched per pixel in the post pass instead, the ten reference scenes' mean
// SSIM was 0.0002 higher for 1.16x the camera frame against 1.049x (docs/performance.md,
// "Eighteenth session").
//
// Screen-space ray marching (McGuire & Mara 2014, "Efficient GPU screen-space ray tracing",
// JCGT 3(4)): from the surface point P along the view's mirror direction R = reflect(-V, N), at
// SELF_REFLECTION_STEPS points spaced geometrically (each SELF_REFLECTION_GROWTH times the last,
// from SELF_REFLECTION_FIRST, slid by up to a step by the texel's phase, mirror_march_phase.glsl:
// the mesh is normalised to 2 units across, mesh.cpp, so the last point is 0.62-1.07 units out,
// a third to a half of the object, and the points are densest near P, where the creases are),
// stepped in clip space (the projection is linear in homogeneous coordinates). The
// first point behind the depth buffer's surface ends it: a hit where that surface lies within the
// last step (plus two pixels' footprint) of the point, else the ray passed behind a part (no light);
// a hit's step is then bisected to the crossing (self_reflection_refined, since session 25).
// 10 points: 16 (x 1.38) gain 0.0006 of the ten reference scenes' mean SSIM for 1.6x the march;
// a march reaching under 0.5 misses the wall of tests/self_reflection_gl_test.cpp at 0.45.
// Approximations, each stated:
// - a mirror: the GGX lobe at alpha = roughness^2 (0.0225 for the reference stone, 1.3 degrees)
//   is narrower than the march resolves; the lobe's albedo is taken as Fresnel's exact factor at
//   the view's cosine (Smith's masking takes under 2 % off up to 85 degrees at that alpha,
//   bounce.glsl). Rougher stones blur their reflection; this keeps it sharp;
// - only what the camera sees (screen space): parts hidden behind others or facing away are not
//   mirrored here; where this march finds nothing, the lighting pass marches the ray again against
//   the light's entry and exit layers for the glowing exit faces behind a part (hidden_mirror.glsl,
//   since session 22), and the bounce's mirrored part, from the light's map, stands in for the rest;
// - the radiance leaving the hit is its diffuse part, the blurred entering light there
//   (its nearest blur texel), times P's albedo (applied with P's own light by the post pass), not the
//   hit's: exact for a flat stone, off by the veins' contrast on a veined one (the bounce's
//   mirrored part makes the same choice); the hit's own highlight is not mirrored.
// Measured (tests/self_reflection_gl_test.cpp): a plate mirroring a lit wall at N.V 0.2 and 0.45,
// 0.99-1.02 of F x the wall's radiance.
// A march whose every point lay in front of the depth buffer returns SELF_REFLECTION_ESCAPED: the
// ray crossed 0.62 units of space the camera sees empty and meets nothing there (see below).
// Needs from the includer: u_depth, u_view_proj, surface_point.

const int SELF_REFLECTION_STEPS = 10;
const float SELF_REFLECTION_FIRST = 0.004;  // world units: about a pixel of the 800^2 frame
const float SELF_REFLECTION_GROWTH = 1.75;

// The mirror ray escaped (session 26): all SELF_REFLECTION_STEPS points of the march lay in front of
// the depth buffer, so along its first 0.62 units the ray runs through space the camera sees empty
// -- head-on faces, whose ray runs back toward the camera, and faces turned out from the object.
// Past that it meets the surround (black in the reference scenes) or, rarely, a far part. There
// Cycles' mirror (the GGX lobe at alpha 0.0225) sees the surround in its core and lit parts only in
// its tail: GGX's half-vector cumulative tan^2 / (alpha^2 + tan^2), the reflected angle twice the
// half vector's, leaves alpha^2 / (alpha^2 + tan^2 5 deg) = 6 % of the lobe beyond 10 degrees of
// the mirror ray (29 % beyond 4, 1.6 % beyond 20). The bounce's mirrored part (bounce.glsl, a
// Phong lobe of exponent 16, about 14 degrees, so that 49 samples resolve it) stands for the
// whole lobe; where the ray escaped it is scaled to that tail, SELF_REFLECTION_ESCAPED_TAIL
// (lighting.frag.glsl). Measured against Cycles' glossy indirect light on dragon-side (main
// 84747ad): where neither march hits, the mirrored part was 1.40x Cycles' there, a broad sheen
// over the head-on coils where Cycles' mirror is dark; on faces at N.V >= 0.8, 1.50x
// (docs/quality.md, "Twenty-sixth session"). A ray that passed behind a part (-1) may meet a
// face hidden there, which the bounce's whole lobe stands for, as before; off screen also -1.
const ivec2 SELF_REFLECTION_ESCAPED = ivec2(-3);
const float SELF_REFLECTION_ESCAPED_TAIL = 0.06;

// The crossing within the step from `before` (in front of the depth buffer) to `behind` (behind it,
// at pixel q), refined by SELF_REFLECTION_REFINE bisections: the pixel of the last point found
// behind. The geometric steps put the first point behind the surface up to a step (0.43 of the
// ray's length so far) past where the ray meets it, and read the light there: further along the
// mirrored part, in from its edge. Back-lit, a part glows most near its rims, where the rays from
// the creases beside it meet it, so the overshoot read the darker inside: on dragon-back, where the
// march hit, Cycles' mirror image was 2.4x F x Cycles' own light at the pixel the march read, 1.9x
// with the crossing bisected (dragon-side, lit from the side: 0.96 and 1.10), and 17 % of the hits
// (3 % bisected) lay where the ray met the surface from behind (R.N_S > 0), i.e. had passed behind
// a part the step's tolerance took for a hit. Four bisections take the step to 1/16 of its length,
// about a pixel of the 800^2 frame where the ray is 0.25 long; the ten reference scenes' mean SSIM
// 0.93923 -> 0.94039 (two: 0.94010; six: 0.94038), every scene up (dragon-side +0.0050;
// docs/quality.md, "Twenty-fifth session"). A point found behind at another pixel than P's is a
// crossing there; one in front moves the bracket on (a bisection of the crossing step, the usual
// refinement of a screen-space march's hit).
const int SELF_REFLECTION_REFINE = 4;
// behind: in, the step's far end; out, the ray's parameter at the crossing's point behind q's surface.
ivec2 self_reflection_refined(ivec2 px, ivec2 size, vec4 clipP, vec4 clipR, float before, inout float behind, ivec2 q) {
  for (int b = 0; b < SELF_REFLECTION_REFINE; ++b) {
    float mid = 0.5 * (before + behind);
    vec4 clip = clipP + mid * clipR;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    ivec2 m = ivec2(uv * vec2(size));
    float d = textureLod(u_depth, uv, 0.0).r;  // the G-buffer's depth, GL_NEAREST (as the march's)
    if (m != px && d < 1.0 && ndc.z * 0.5 + 0.5 > d) {
      behind = mid;
      q = m;
    } else {
      before = mid;
    }
  }
  return q;
}

// The pixel whose surface P's mirror ray meets, or ivec2(-1) where it meets none the camera sees
// (it leaves the screen or passes behind a part), or SELF_REFLECTION_ESCAPED where it runs out of
// steps with every point in front of the depth buffer. px: P's pixel; depth: its depth-buffer
// value; V: toward the camera; phase (0 ... 1): the points slid by that fraction of a step, the
// first at SELF_REFLECTION_FIRST x SELF_REFLECTION_GROWTH^phase (mirror_march_phase.glsl: a
// start stratified over the texels, so that their rays do not step over a thin part together).
// hit_t: where the march hit, the ray's parameter at its point behind the hit pixel's surface
// (mirror_lit_face.glsl reads how far behind); else 0.
ivec2 self_reflection_hit(ivec2 px, float depth, vec3 P, vec3 N, vec3 V, float phase, out float hit_t) {
  hit_t = 0.0;
  ivec2 size = textureSize(u_depth, 0);
  // One pixel's footprint at P, for the hit's tolerance.
  float pixel = distance(surface_point((vec2(px) + vec2(1.5, 0.5)) / vec2(size), depth), P);
  vec3 R = reflect(-V, N);
  // The ray in clip space: the projection is linear in homogeneous coordinates.
  vec4 clipP = u_view_proj * vec4(P, 1.0), clipR = u_view_proj * vec4(R, 0.0);
  float t = SELF_REFLECTION_FIRST * pow(SELF_REFLECTION_GROWTH, phase), previous = 0.0;
  // The hit's pixel, bisected after the loop: llvmpipe runs a branch for its whole block of lanes
  // where any lane takes it, so inside the loop the bisection ran at each step where some lane hit
  // (the camera frame's lighting pass +15.4 M instructions on the dragon at 800^2, against +2.2 M here;
  // docs/performance.md, "Twenty-fifth session").
  ivec2 hit = ivec2(-1);
  float hit_depth = 0.0;
  for (int i = 0; i < SELF_REFLECTION_STEPS; ++i) {
    vec4 clip = clipP + t * clipR;
    vec3 ndc = clip.xyz / clip.w;
    if (clip.w <= 0.0 || any(greaterThan(abs(ndc.xy), vec2(1.0)))) return ivec2(-1);  // off screen
    vec2 uv = ndc.xy * 0.5 + 0.5;
    ivec2 q = ivec2(uv * vec2(size));
    // q's depth through the sampler (the G-buffer's depth is GL_NEAREST: floor(uv x size), q), for
    // fewer instructions than texelFetch on llvmpipe (nearest_texel.glsl); uv = 1 exactly (the
    // frame's last edge) reads the last texel, where texelFetch read 0 beyond it.
    float d = textureLod(u_depth, uv, 0.0).r;
    if (q != px && d < 1.0 && ndc.z * 0.5 + 0.5 > d) {
      hit = q;
      hit_depth = d;
      break;
    }
    previous = t;
    t *= SELF_REFLECTION_GROWTH;
  }
  if (hit.x < 0) return SELF_REFLECTION_ESCAPED;  // every point in front of the depth buffer
  // Passed behind a part, not into the hit pixel's surface: tested once, after the loop, with the
  // values of the step that broke it (hit, hit_depth, t, previous), not inside the loop, where
  // llvmpipe ran the test's body at every step for the whole block of lanes (the same hits, the
  // camera frame's lighting pass 2.5 M instructions fewer on the dragon at 800^2;
  // docs/performance.md, "Thirtieth session: ... s30-cost").
  vec3 S = surface_point((vec2(hit) + 0.5) / vec2(size), hit_depth);
  if (distance(S, P + R * t) > (t - previous) + 2.0 * pixel) return ivec2(-1);  // passed behind a part
  // The march hit: `previous` and `t` bracket the crossing.
  hit = self_reflection_refined(px, size, clipP, clipR, previous, t, hit);
  hit_t = t;
  return hit;
}
