#version 450 core
// Last pass: from linear HDR light to the display. For `marble` it first composes the frame:
// the subsurface-blurred light that entered the stone (half resolution, upsampled) times the
// albedo, plus what the surface reflects (GGX and the environment, computed here so that a
// change of gloss re-runs this pass only); then exposure, the Khronos PBR Neutral tone map
// and the sRGB transfer function. The paper's modes and the buffer views were never
// colour-managed: they pass through as they are.
//
// The `marble` frame's diffuse part (blurred light x albedo) comes from one of three sources,
// a constant of the program (DIFFUSE_SOURCE, chosen per frame by the renderer from what changed):
//   0  the albedo changed (the view moved, or the pattern): the pattern is evaluated here, and
//      the albedo and the diffuse part are also written out (o_albedo, o_diffuse) for later frames;
//   1  the light changed, the albedo did not: the stored albedo, the diffuse part written out;
//   2  neither changed (gloss, exposure, background): the stored diffuse part, one read, and the
//      stored albedo for the retro-reflection (which the gloss changes: not in the diffuse part).
// On llvmpipe every texture read costs about as much over the frame as a simple pass's
// arithmetic, and a pass of its own costs more: the albedo pass is not run for `marble`.
//
// SURFACE_REUSE (source 0 only; a constant of the program, chosen by the renderer): in a frame in
// which only the pattern changed, everything but the albedo is what the previous frame computed.
//   0  nothing stored or read (the camera's and the light's frames: nothing to reuse);
//   1  a frame that changed only the pattern: it also writes the upsampled blurred light and the
//      reflected light (o_surface_light, o_surface_reflected, RGBA32F: the values exactly; the
//      retro-reflection's factor in o_surface_reflected's alpha);
//   2  the next such frames: they read those two back instead of the upsample, the shadow's
//      taps, GGX and the environment (about a third of the contour presets' pattern frame).
// The values are stored as 32-bit floats, the precision they are computed in, and combined with
// the albedo by the same operations, so a reused frame equals a fresh one bit for bit
// (PostSurfaceReuse tests).
#include "gbuffer.glsl"
#include "paper_shading.glsl"
#include "deferred_common.glsl"
#include "subsurface_common.glsl"
#include "nearest_texel.glsl"
#include "mirror_hit_light.glsl"

#ifndef SURFACE_REUSE
#define SURFACE_REUSE 0
#endif
#if COMPOSE_MARBLE == 1 && DIFFUSE_SOURCE == 0
#include "marble_pattern.glsl"
#include "pattern_at_pixel.glsl"
#endif

in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_diffuse;  // DIFFUSE_SOURCE 0 and 1: blurred light x albedo, linear
layout(location = 2) out vec4 o_albedo;   // DIFFUSE_SOURCE 0: the pattern's colour
layout(location = 3) out vec4 o_surface_light;      // SURFACE_REUSE 1: the upsampled blurred light
layout(location = 4) out vec4 o_surface_reflected;  // SURFACE_REUSE 1: the reflected light
layout(binding = UNIT_POST_SURFACE_LIGHT) uniform sampler2D u_surface_light;          // SURFACE_REUSE 2
layout(binding = UNIT_POST_SURFACE_REFLECTED) uniform sampler2D u_surface_reflected;  // SURFACE_REUSE 2
layout(binding = UNIT_POST_MIRROR_HIT) uniform sampler2D u_mirror_hit;  // marble: the lighting pass's mirror hits
layout(binding = UNIT_POST_HDR) uniform sampler2D u_hdr;       // other modes: the lighting pass's image
layout(binding = UNIT_POST_BLURRED) uniform sampler2D u_blurred;   // marble: blurred entering light, half resolution
layout(binding = UNIT_POST_DIFFUSE) uniform sampler2D u_diffuse;   // marble, DIFFUSE_SOURCE 2: the stored diffuse part
layout(binding = UNIT_POST_ALBEDO) uniform sampler2D u_albedo;
layout(binding = UNIT_POST_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_POST_LIGHT_SHADOW) uniform sampler2DShadow u_light_shadow;
// Composing `marble` or passing another mode through: a constant of the program
// (COMPOSE_MARBLE 0 or 1, defined by the post pass; gl/program_variants.h).
const int u_compose_marble = COMPOSE_MARBLE;
uniform int u_output_linear;      // 1: the linear HDR image with coverage in alpha (--hdr)
uniform int u_tone_map;
uniform int u_paint_background;   // 0 for views that are not of the camera's G-buffer
uniform int u_luma_alpha;         // 1: alpha holds the display colour's luma, for FXAA (else 1)
uniform float u_exposure_scale;   // 2^exposure
uniform vec3 u_background;
uniform float u_ior;
uniform float u_roughness;
uniform float u_env_intensity;

#include "marble_shading.glsl"
#include "environment.glsl"
#include "marble_light.glsl"
#include "self_reflection.glsl"

#include "display.glsl"

// A frame drawn from stored values must equal one that computed them: values are used as
// their textures store them -- the albedo as 8-bit (RGBA8), the diffuse part as half floats
// (RGBA16F), both rounded to nearest as the conversions on store are. An 8-bit value is read
// back as c x (1/255), as llvmpipe converts it, not c / 255, which differs from it by one ulp for
// some c: enough to tip a half-float or an 8-bit output the other way now and then (session 18:
// one pixel of PassFixture.ModesReuseOnlyTheAlbedoTheirOwnPassWrote, one level). A GPU that
// divides exactly would want c / 255.
vec3 as_stored_unorm8(vec3 v) { return roundEven(clamp(v, 0.0, 1.0) * 255.0) * (1.0 / 255.0); }
vec3 as_stored_half(vec3 v) {
  return vec3(unpackHalf2x16(packHalf2x16(v.rg)), unpackHalf2x16(packHalf2x16(vec2(v.b, 0.0))).x);
}

// The texel of the blur's resolution nearest full-resolution pixel p >= 0, (p + scale / 2) / scale,
// as shifts: the scale is 1 or 2 (subsurfaceScale), where they are that division exactly. llvmpipe
// has no vector integer division: it divided lane by lane, 3.85 M instructions of the post pass of
// the dragon's 800^2 camera frame for the two calls (docs/performance.md, "Twenty-seventh session:
// ... s27-cost").
ivec2 nearest_blur_texel(ivec2 p) {
  int s = u_scale >> 1;
  return (p + s) >> s;
}

// The diffuse part at a surface pixel: the subsurface-blurred light, with the stone's own light
// mirrored in the surface, x the albedo (see the top). V: toward the camera; hit: where the
// surface's mirror ray meets the object on screen (self_reflection_hit), or -1. albedo: the
// albedo it used (source 2: the stored one), for the retro-reflection (marble_compose).
vec3 marble_diffuse(ivec2 px, float depth, vec3 N, vec3 V, ivec2 hit, out vec3 albedo) {
#if DIFFUSE_SOURCE == 2
  albedo = nearest_texel(u_albedo, px).rgb;  // GL_NEAREST, px on screen (nearest_texel.glsl)
  return nearest_texel(u_diffuse, px).rgb;
#else
#if DIFFUSE_SOURCE == 0
  albedo = as_stored_unorm8(albedo_at_pixel(v_uv, depth, N));
  o_albedo = vec4(albedo, 1.0);
#else
  albedo = nearest_texel(u_albedo, px).rgb;
#endif
#if SURFACE_REUSE == 2
  vec3 light = nearest_texel(u_surface_light, px).rgb;
#else
  precise vec3 light = upsample_blurred(u_blurred, px, depth);
  // The stone's own light mirrored in its surface (self_reflection.glsl): reflected light, but the
  // hit's albedo is taken as P's, so it joins the light the albedo multiplies. The blurred light
  // of one blur texel at the hit, on the hit's own surface, not the depth-aware upsample: the hit
  // lies on a surface the march found, and the upsample's four taps cost 10.6 M instructions of the
  // dragon's 800^2 camera frame for 0.0001 of the reference scenes' mean SSIM (docs/performance.md).
  if (hit.x >= 0) {
    // The blur texel on the hit's own surface (mirror_hit_light.glsl): the nearest one unless its
    // view depth lies farther from the hit's than one surface's (upsample_blurred's tolerance).
    ivec2 texel = min(nearest_blur_texel(hit), textureSize(u_blurred, 0) - 1);
    float hit_depth = view_depth(nearest_texel(u_depth, hit).r);  // GL_NEAREST, hit on screen
    light += fresnel_dielectric(max(dot(N, V), 0.0), u_ior) *
             mirror_hit_light(u_blurred, texel, hit_depth, same_surface_tolerance_mm(hit_depth) / u_mm_per_unit);
  }
#if SURFACE_REUSE == 1
  o_surface_light = vec4(light, 1.0);
#endif
#endif
  precise vec3 d = as_stored_half(light * albedo);
  o_diffuse = vec4(d, 1.0);
  return d;
#endif
}

// Where pixel px's mirror ray meets the object on screen, or -1 (-2: it meets a surface hidden from
// the camera, whose light the lighting pass added, hidden_mirror.glsl): the lighting pass marched it for
// the entering texel nearest px (texel h sits at pixel h * scale, blur_texel.glsl), from that
// texel's surface point; within a texel the pixels share it (the mirror image at the entering
// light's resolution, half by default).
ivec2 mirror_hit_at(ivec2 px) {
  ivec2 t = min(nearest_blur_texel(px), textureSize(u_mirror_hit, 0) - 1);
  return ivec2(nearest_texel(u_mirror_hit, t).xy);
}

// The change of the half vector H (at P, normal N) from this pixel to its neighbour toward +axis
// (axis: (1, 0) or (0, 1)). Across a pixel the highlight's argument is the normal relative to the
// half vector, and both turn: the view vector with the camera's ray, and a point light's vector with
// the surface point. The neighbour's point is taken on P's tangent plane, where its ray meets it, so
// a depth edge beside P does not enter. Left out (the half vector held at the pixel centre's, as in
// session 19's s19-glints), a lobe narrower than a pixel was integrated over a footprint too small:
// on the test sphere of Specular.SubPixelHighlightKeepsItsPower (a pixel's normals 0.05 rad, the
// half vector's 0.0075 rad the other way) the pixel holding the lobe read 1.19 of its brute-force
// value (docs/quality.md, "Nineteenth session: ... s19-glints2").
vec3 half_vector_step(vec3 P, vec3 N, vec3 H, vec2 axis) {
  vec3 ray = surface_point(v_uv + axis / vec2(textureSize(u_depth, 0)), 1.0) - u_camera_pos;
  float along = dot(ray, N);
  if (abs(along) < 1e-6 * length(ray)) return vec3(0.0);  // the neighbour's ray grazes the plane
  vec3 Q = u_camera_pos + ray * (dot(P - u_camera_pos, N) / along);
  return normalize(normalize(u_camera_pos - Q) + light_vector(Q)) - H;
}

// The `marble` frame at a surface pixel (normal N): the diffuse part + reflected light, the
// highlight integrated over the pixel's normals (bx, ax, by, ay: their change to its neighbours,
// footprint_normal_steps). Where
// the mirror ray meets the object itself, the object is what the surface mirrors (marble_diffuse,
// or hidden_mirror.glsl's light in the entering light), not the environment behind it: the
// environment's reflection is left out there. The light's retro-reflection (marble_retro_reflected,
// Cycles' Principled lobe beside the walk) is reflected too, but by the albedo: added here, after
// the diffuse part, which a gloss change reuses (DIFFUSE_SOURCE 2).
vec3 marble_compose(float depth, vec3 N, vec3 bx, vec3 ax, vec3 by, vec3 ay) {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 V = vec3(0.0);
  ivec2 hit = ivec2(-1);
#if SURFACE_REUSE == 2
  vec4 stored = nearest_texel(u_surface_reflected, px);  // GL_NEAREST, px on screen
  vec3 reflected = stored.rgb;
  float retro = stored.a;
#else
  vec3 P = surface_point(v_uv, depth);
  V = normalize(u_camera_pos - P);
  hit = mirror_hit_at(px);
  vec3 L = light_vector(P);
  float falloff = light_falloff(light_distance_of(P));
  vec3 E = u_light_radiance * falloff;  // light_irradiance
  float visible = bilinear_visibility(P, N, u_light_view_proj, u_light_texel_world);
  vec3 H = normalize(V + L);
  vec3 hx = half_vector_step(P, N, H, vec2(1.0, 0.0)), hy = half_vector_step(P, N, H, vec2(0.0, 1.0));
  precise vec3 reflected = marble_reflected(N, V, L, E, visible, u_ior, u_roughness, bx - hx, ax - hx, by - hy, ay - hy,
                                             hit.x == -1 ? u_env_intensity : 0.0);
  precise float retro = marble_retro_reflected(N, V, L, falloff, visible, u_roughness);
#if SURFACE_REUSE == 1
  o_surface_reflected = vec4(reflected, retro);
#endif
#endif
  // Stored or computed, the same values and the same sum (a multiply-add fused across this
  // sum in one program and not the other would break that: PassFixture.PatternOnlyFrames* checks).
  // `precise` (GLSL 4.50, 4.7.1) on the light, the diffuse part, the reflected light and the sum:
  // these are computed by several variants of this program (DIFFUSE_SOURCE, SURFACE_REUSE), and
  // a cached frame must equal a fresh one bit for bit; without it a compiler may fuse a multiply
  // with an add in one variant and not in another (NVIDIA's does, per program; llvmpipe's does
  // not), which GLSL allows. docs/performance.md, "Eighteenth session".
  vec3 albedo;
  precise vec3 diffuse = marble_diffuse(px, depth, N, V, hit, albedo);
  precise vec3 composed = diffuse + reflected + albedo * (u_light_radiance * retro);
  return composed;
}

// The change of the normal from pixel p to its neighbour q (toward +axis: q - p, or p - q when q
// lies on the minus side, `sign`); false where q is off the object or outside the frame.
// interpolated: q's interpolated normal (the specular normal texture's zw), not its bent one (xy).
bool normal_step(ivec2 q, float q_depth, vec3 N, float sign, bool interpolated, out vec3 step) {
  step = vec3(0.0);
  if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, textureSize(u_depth, 0)))) return false;
  if (q_depth >= 1.0) return false;
  vec4 stored = nearest_texel(u_normal, q);
  step = sign * (decode_normal(interpolated ? stored.zw : stored.xy) - N);
  return true;
}

// The normal's change to the four neighbours of surface pixel p (normal N), each toward +axis
// (bx, ax: before and after it along x; by, ay along y), a depth edge on one side mirrored from
// the other (footprint_axis_steps). The neighbour inside the 2x2 quad comes from the fine screen
// derivatives (d*_quad: N's and coverage's), the one outside it from two texel reads: half the
// reads of fetching all four (post pass +21 M instructions a frame on the dragon at 800^2 with
// four; docs/performance.md, "Sixteenth session").
// kept: the valid-reflection rule kept p's normal (geometry.frag.glsl); its steps then go to the
// neighbours' interpolated normals, not their bent ones (d*_quad: the interpolated normal's
// derivatives). Cycles bends each ray's normal where that ray's reflection falls below its
// triangle (kernel/closure/bsdf_util.h, `ensure_valid_reflection`, called for the Principled
// BSDF's normal in kernel/svm/closure.h, `svm_node_closure_bsdf`), so from a kept pixel's centre
// toward a bent neighbour the normals stay the interpolated ones until the view's reflection
// crosses that threshold, which on the silhouette rows lies mostly beyond the midpoint between
// the two centres; a step to the neighbour's bent normal swept the kept pixel's footprint over
// normals no ray there has: on bunny-back's back rim the 800^2 row below the bent one read
// 1506 / 1193 against Cycles' 1201 / 1009 (docs/quality.md, "Twentieth session: ... s20-bunny2").
void footprint_normal_steps(ivec2 p, vec3 N, bool kept, vec3 dndx_quad, vec3 dndy_quad, float don_dx, float don_dy,
                            vec2 outer_depths, out vec3 bx, out vec3 ax, out vec3 by, out vec3 ay) {
  // The quad pairs columns 2i | 2i+1 (and rows): an even pixel's partner is at +1, its outer
  // neighbour at -1; an odd one's the other way round. The quad's derivative is toward +axis.
  bool even_x = (p.x & 1) == 0, even_y = (p.y & 1) == 0;
  vec3 outer_x, outer_y;
  bool outer_x_on = normal_step(ivec2(even_x ? p.x - 1 : p.x + 1, p.y), outer_depths.x, N, even_x ? -1.0 : 1.0, kept, outer_x);
  bool outer_y_on = normal_step(ivec2(p.x, even_y ? p.y - 1 : p.y + 1), outer_depths.y, N, even_y ? -1.0 : 1.0, kept, outer_y);
  bool quad_x_on = don_dx == 0.0, quad_y_on = don_dy == 0.0;
  bx = even_x ? outer_x : dndx_quad;
  ax = even_x ? dndx_quad : outer_x;
  by = even_y ? outer_y : dndy_quad;
  ay = even_y ? dndy_quad : outer_y;
  footprint_axis_steps(bx, even_x ? outer_x_on : quad_x_on, ax, even_x ? quad_x_on : outer_x_on);
  footprint_axis_steps(by, even_y ? outer_y_on : quad_y_on, ay, even_y ? quad_y_on : outer_y_on);
}

// The depths of pixel p and of its outer neighbours along x and y (footprint_normal_steps: -1 for
// an even column or row, +1 for an odd one), from one gather of the 2 x 2 texels they share: the
// texels' values as stored, as three nearest reads give them (clamped to the edge outside the
// frame, where normal_step does not use them); one read instead of three: the post pass of the
// dragon's 800^2 camera frame 135.76 -> 134.93 M instructions (docs/performance.md, "Twenty-seventh
// session: ... s27-cost"). Four-channel gathers do not pay so: the upsample's four reads as four
// gathers cost +5.9 M.
// Returns p's depth; outer: the x and the y neighbour's.
float depths_at(ivec2 p, out vec2 outer) {
  bool even_x = (p.x & 1) == 0, even_y = (p.y & 1) == 0;
  ivec2 lo = ivec2(even_x ? p.x - 1 : p.x, even_y ? p.y - 1 : p.y);  // the block's lower-left texel
  // (lo.x, lo.y + 1), (lo.x + 1, lo.y + 1), (lo.x + 1, lo.y), (lo.x, lo.y): GL's gather order.
  vec4 g = textureGather(u_depth, vec2(lo + 1) / vec2(textureSize(u_depth, 0)), 0);
  vec2 upper = even_x ? g.yx : g.xy, lower = even_x ? g.zw : g.wz;  // (p's column, the other)
  vec2 row = even_y ? upper : lower, other_row = even_y ? lower : upper;
  outer = vec2(row.y, other_row.x);
  return row.x;
}

void main() {
  vec2 outer_depths;
  float depth = depths_at(ivec2(gl_FragCoord.xy), outer_depths);
  bool surface = depth < 1.0;
  vec3 c;
  if (u_compose_marble == 1) {
    // The fine derivatives are taken here, where every pixel of a 2x2 quad runs (none is defined
    // inside a branch some of them skip); background pixels hold N = 0 and on = 0.
    // xy: the normal for the reflection terms (bent by the valid-reflection rule in `marble`
    // mode); zw: the interpolated normal, the same bits where the rule kept it (a two-channel
    // texture, when the rule is off, reads (0, 1) there: counted as bent, the steps as before).
    vec4 stored = surface ? nearest_texel(u_normal, ivec2(gl_FragCoord.xy)) : vec4(0.0);
    vec3 N = surface ? decode_normal(stored.xy) : vec3(0.0);
    bool kept = stored.xy == stored.zw;
    float on = surface ? 1.0 : 0.0;
#if SURFACE_REUSE == 2
    vec3 bx = vec3(0.0), ax = bx, by = bx, ay = bx;  // in the stored reflected light
#else
    vec3 n = kept ? N : decode_normal(stored.zw);  // the interpolated normal
    vec3 dndx_quad = dFdxFine(N), dndy_quad = dFdyFine(N);
    vec3 dnidx_quad = dFdxFine(n), dnidy_quad = dFdyFine(n);
    float dondx = dFdxFine(on), dondy = dFdyFine(on);
    vec3 bx = vec3(0.0), ax = bx, by = bx, ay = bx;
    if (surface)
      footprint_normal_steps(ivec2(gl_FragCoord.xy), N, kept, kept ? dnidx_quad : dndx_quad, kept ? dnidy_quad : dndy_quad,
                             dondx, dondy, outer_depths, bx, ax, by, ay);
#endif
    c = surface ? marble_compose(depth, N, bx, ax, by, ay) : vec3(0.0);
  } else {
    c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
  }
  if (u_output_linear == 1) {
    // Coverage: where the camera saw the object. The light-depth view (no background to
    // paint) shows the light's map: all of it is content.
    o_color = vec4(c, surface || u_paint_background == 0 ? 1.0 : 0.0);
    return;
  }
  if (u_tone_map == 1) c = srgb_encode(pbr_neutral(c * u_exposure_scale));
  // The background colour is a display colour: it is not tone mapped.
  if (u_paint_background == 1 && !surface) c = u_background;
  c = clamp(c, 0.0, 1.0);
  o_color = vec4(c, u_luma_alpha == 1 ? fxaa_luma(c) : 1.0);
}
