#version 450 core
// Screen-space subsurface scattering (after Jimenez et al. 2015, "Separable Subsurface
// Scattering"): the light that entered the stone is spread over the surface by a diffusion
// profile, one axis per pass. The profile is the 1D marginal of the random walk Cycles runs in
// the same stone, per channel, tabulated out to where red leaves 0.2 % of its light
// (src/marble/render/subsurface_profile.h; Burley's normalized diffusion before session 18);
// its width on screen follows the millimetre scale and the surface's depth, and samples
// across a silhouette (a depth jump, or the background) are left out.
//
// Both passes run at half resolution by default, as the lighting pass that feeds them: the
// profile is smooth, so a quarter of the pixels carry it (render.subsurface_resolution "full"
// runs them at full resolution). Blur texel h stands for one of its full-resolution pixels
// (blur_texel.glsl: h * scale, or another of its 2x2 where that one is background).
// Alpha is that pixel's view depth (0: no stone) in the input, between the passes and after
// them: it says which taps are on the same surface here and, in the post pass, which texels
// the depth-aware upsample may use (subsurface_common.glsl). One read per tap, then (there was
// a second, of the G-buffer's depth): on llvmpipe each texture read costs about as much over
// the frame as the rest of a tap.
// Only the surface is shaded (its depth test: BlurDepthPass).
#include "gbuffer.glsl"
#include "subsurface_common.glsl"

layout(location = 0) out vec4 o_color;
// The lighting pass's entering light (first pass) or the first pass's result (second), at the
// blur's resolution; alpha: view depth, 0 off the stone.
layout(binding = UNIT_SCREEN_INPUT) uniform sampler2D u_entering;
// The same texture through a GL_NEAREST sampler object (SubsurfaceBlurPass): the centre's one
// whole-texel read, for fewer instructions than texelFetch, the same bits (nearest_texel.glsl).
layout(binding = UNIT_SCREEN_INPUT_TEXELS) uniform sampler2D u_entering_texels;
#include "nearest_texel.glsl"
uniform vec2 u_direction;          // (1,0) then (0,1)
// Taps per side, 1..MAX_TAPS (as many as the reach spans in texels): a constant of the program
// (BLUR_TAPS, defined by SubsurfaceBlurPass), so that the loop is unrolled and each tap reads its
// offset and weight below at a constant index. With the count a uniform, the index was the loop's
// counter, which llvmpipe cannot know to be the same in every lane: it gathered both arrays lane
// by lane, four 8-lane gathers per tap (docs/performance.md, "Tenth session").
const int u_taps = BLUR_TAPS;
uniform float u_offsets_mm[MAX_TAPS + 1];  // tap i's distance from the centre, mm (subsurface_profile.h)
uniform vec3 u_weights[MAX_TAPS + 1];  // the profile's share at tap i, computed on the CPU
// The kernel's core (subsurface_profile.h, SubsurfaceKernel): the share of the light that leaves
// at the entry's own texel, beyond what the two passes' product of marginals puts there (the
// walk's exits are radially symmetric, the product is not). Added by the second pass from the
// lighting pass's own texel (u_entering_own, GL_NEAREST); 0 in the first pass. The taps' weights
// are the residual marginal's, so the marginal along either axis is still the walk's.
uniform vec3 u_core;
layout(binding = UNIT_SCREEN_INPUT_OWN) uniform sampler2D u_entering_own;

// How fast the profile falls past tap i, per mm and channel (its local log slope; 0 at i = 0):
// subsurface_profile.h, SubsurfaceKernel::decayPerMm.
uniform vec3 u_decay_per_mm[MAX_TAPS + 1];

// MAX_TAPS: render/shader_constants.h

// One tap of the blur, k texel steps of the profile out on the side `side` (+1 or -1) of the centre
// h: its weighted light and weight added to sum and weight; prev is the depth of the tap before it
// on that side (the centre's for k = 1), updated to this one's (-1 where this one is left out).
void blur_tap(ivec2 h, int k, float side, vec2 input_size, float texels_per_mm, float stretch, vec4 centre,
              float depth, inout float prev, inout vec3 sum, inout vec3 weight) {
  vec2 t = vec2(h) + 0.5 + u_direction * (side * u_offsets_mm[k] * texels_per_mm);
  vec4 e = texture(u_entering, t / input_size);
  vec3 w0 = u_weights[k];
  // Off the stone, or across a silhouette (more than the reach away in depth): the tap's
  // weight takes the centre's own light, not the other taps' (after Jimenez et al. 2015's
  // "follow surface" fallback). Such a tap stands for this surface's continuation the camera
  // cannot see (it curves away past the silhouette, or lies behind the part in front); the
  // centre is the nearest estimate of the light entering there. Left out and renormalised
  // over the visible taps instead, the kernel turned one-sided at every silhouette and
  // depth step and pulled the inner taps' light out to the rim: the ten reference scenes'
  // mean SSIM 0.9523 -> 0.9531 with this, the back-lit buddha 0.8914 -> 0.8905 the one loss
  // (docs/quality.md, "Twenty-sixth session: the blur's left-out taps"). A tap between stone
  // and background reads a depth scaled down by its coverage, so it counts as off the stone
  // unless nearly all stone.
  if (e.a <= 0.0 || abs(e.a - depth) * u_mm_per_unit > u_reach_mm) {
    sum += w0 * centre.rgb;
    weight += w0;
    prev = -1.0;
    return;
  }
  // The profile is read at the tap's distance in 3D, not only along the screen: x / stretch mm
  // across the screen (the tap's screen offset) and dz mm in view depth. On the smooth surface
  // the slope above predicts, that is x itself (sqrt(x^2 / (1 + s^2) + s^2 x^2 / (1 + s^2))); a
  // tap on another surface -- a part in front of or behind this one across a silhouette, a step
  // -- lies farther, and the light entering there reaches here only as the walk's profile
  // allows at that distance: its weight falls by exp(-decay (d - x)), the profile's own log
  // slope past tap i carried on to d. Before, such a tap weighed as if it lay on this surface
  // x away, out to a depth difference of the whole reach (16 mm in the issue's stone): the
  // back-lit statues' lit rims and glowing thin parts spread their light into the dark body
  // behind and beside them (docs/quality.md, "Twenty-sixth session: the blur's taps at their
  // 3D distance": the dark body 1.4-2x Cycles'). A tap nearer in 3D than x (a curved surface)
  // keeps its weight. The weight the 3D distance takes off goes to the centre's own light, as
  // for a tap off the stone above (the light entering this surface's unseen continuation).
  float xs = u_offsets_mm[k] / stretch, dz = (e.a - depth) * u_mm_per_unit;
  // exp(-f) as 1 / (1 + f + f^2/2 + f^3/6), its Taylor series' first four terms inverted:
  // within 2 % to f = 1, 0.158 for 0.135 at f = 2, 0.077 for 0.050 at f = 3 (a heavier tail
  // where the weight is already small); the ten reference scenes within 0.0001 of the exact
  // exponential, and the blur pass 70.4 M instructions against 76.5 M (the dragon at 800²;
  // 48.9 M before this weight; docs/performance.md, "Twenty-sixth session"). Taken at every
  // tap: a branch around it where it would move the weight by under 1 % cost more on llvmpipe.
  vec3 f = u_decay_per_mm[k] * max(sqrt(xs * xs + dz * dz) - u_offsets_mm[k], 0.0);
  vec3 w = w0;
  w /= 1.0 + f * (1.0 + f * (0.5 + f * (1.0 / 6.0)));
  // The surface this tap stands for. The weights sample the exitance integral of the light entering
  // over the surface, each tap standing for the stretch of the surface its screen interval covers;
  // the centre's own stretch is the same for every tap and cancels in the normalisation (above),
  // but a tap on a face that turns more from the camera than the centre's covers more surface: the
  // lit top of a ledge seen at a few degrees from the wall below it holds in each texel 4-10 times
  // the surface a texel of the wall does. Its measure over the centre's is its own stretch, from
  // the depth step to the tap before it on this side, over the centre's: a, clamped to [1, 4] (a
  // tap on a face turned more toward the camera keeps its weight; 4 bounds a grazing face's).
  // Only on the centre's own surface, a fold, where the tap lies near its nominal distance: across
  // a step to another part the interval between the taps is a gap the camera sees past, not
  // surface, so a fades to 1 as the red 3D excess f (above) reaches 1 (the weight fallen to 0.38).
  // The light of the weight the tap carries beyond its nominal share, w (a - 1), is renormalised
  // with the rest, so that uniform light stays uniform. buddha-side's direct light on the base's
  // side wall just below its lit top went 0.50 -> 0.54 of Cycles'; the ten reference scenes' mean
  // SSIM 0.9531 -> 0.9533, buddha-side and dragon-side +0.0012, the back-lit statues -0.0005 and
  // -0.0006, whose dark body (1.3-1.6x Cycles') takes more of their foreshortened rims
  // (docs/quality.md, "Twenty-seventh session: ... the blur's taps weighed by the surface they cover").
  float a = 1.0;
  if (prev > 0.0) {
    float ds = (u_offsets_mm[k] - u_offsets_mm[k - 1]) / stretch;  // mm of screen between the taps
    float slope = (e.a - prev) * u_mm_per_unit / max(ds, 1e-6);
    a = 1.0 + (clamp(sqrt(1.0 + slope * slope) / stretch, 1.0, 4.0) - 1.0) * max(1.0 - f.r, 0.0);
  }
  prev = e.a;
  sum += w * a * e.rgb + (w0 - w) * centre.rgb;
  weight += w * a + (w0 - w);
}

void main() {
  ivec2 h = ivec2(gl_FragCoord.xy);
  vec2 input_size = vec2(textureSize(u_entering, 0));
  vec4 centre = nearest_texel(u_entering_texels, h);  // h inside: the output is the input's size
  float depth = centre.a;
  // Blur texels per mm at this depth (the taps' distances grow quadratically, subsurfaceTaps). Each tap is read with bilinear filtering at its exact distance: rounded to
  // the nearest texel, narrow profiles lost their shape (SSIM against Cycles on dragon-front
  // 0.765 against 0.757; docs/quality.md).
  float texels_per_mm = u_pixels_per_mm_at_unit_depth / (float(u_scale) * max(depth, 1e-6));
  // The profile is a function of the distance along the surface; a tap's screen offset x lies
  // x sqrt(1 + s^2) away on a surface whose view depth rises by s mm per mm of screen along this
  // pass's axis. So the taps are drawn in by that factor and each samples the profile at its own
  // distance (the weights stay: the measure's stretch is the same for every tap and cancels in
  // the normalisation). Without it the light entering a part was spread sqrt(1 + s^2) times too
  // far over the slanted parts next to it: rims and small creases brighter than Cycles' in the
  // direct light (docs/quality.md, "Twelfth session", item 3, and "Sixteenth session"). The
  // slope comes from the view depth one texel either side (below), so that a depth step (another
  // part behind) is not taken for one; capped where one side is off the stone.
  vec2 one = u_direction / input_size;
  vec2 c = (vec2(h) + 0.5) / input_size;
  float za = texture(u_entering, c + one).a, zb = texture(u_entering, c - one).a;
  float ga = za > 0.0 ? abs(za - depth) : 1e30, gb = zb > 0.0 ? abs(zb - depth) : 1e30;
  // Where both sides are on the stone and agree within 2x, their mean (the central difference:
  // smooth where the surface curves); else the smaller side.
  float g = max(ga, gb) < 2.0 * min(ga, gb) ? 0.5 * (ga + gb) : min(ga, gb);
  float slope = min(g, 1e3) * u_mm_per_unit * texels_per_mm;  // mm of depth per mm of screen
  float stretch = sqrt(1.0 + slope * slope);
  texels_per_mm /= stretch;
  // The taps are read from the centre outward, both sides in one step, so that each side keeps the
  // depth of the tap before it (prev_pos, prev_neg: the surface's measure below; -1 where that tap
  // was left out). The centre is tap 0, its own texel (no read: a bilinear read at a texel's
  // centre is that texel).
  vec3 sum = u_weights[0] * centre.rgb, weight = u_weights[0];
  float prev_pos = depth, prev_neg = depth;
  for (int k = 1; k <= u_taps; ++k) {
    blur_tap(h, k, 1.0, input_size, texels_per_mm, stretch, centre, depth, prev_pos, sum, weight);
    blur_tap(h, k, -1.0, input_size, texels_per_mm, stretch, centre, depth, prev_neg, sum, weight);
  }
  vec3 blurred = sum / max(weight, vec3(1e-8));
  // The core only where the first pass left this texel's light (depth > 0: the same texel of the
  // lighting pass is stone).
  if (u_core != vec3(0.0)) blurred = mix(blurred, nearest_texel(u_entering_own, h).rgb, u_core);
  o_color = depth > 0.0 ? vec4(blurred, depth) : vec4(0.0);
}
