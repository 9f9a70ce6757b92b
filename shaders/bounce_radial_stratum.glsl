// Where across its radius each of the first bounce's inner rings is read, per texel of the bounce
// pass's coarse grid (bounce_gather.frag.glsl). Why: each ring of the gather (r0 to 2 r0, bounce.glsl)
// is read at one radius per sector, and with the same radius at every texel an emitter is found only
// near that radius: the first bounce lies in streaks 0.5-2x Cycles' across buddha-side's robe and
// along dragon-back's coils, where the rings' radii cross the folds (docs/quality.md, "Twenty-seventh
// session: why the first bounce is misplaced"; four radii a ring, four times the samples, removed them
// for +213 M instructions of the dragon's 800^2 camera frame). Here the four texels of each 2 x 2
// block, which already turn the pattern by four quarter-steps and are evened out equally by the
// deinterleave's tent (bounce_deinterleave.frag.glsl), also read four radii: the four equal-area
// strata of the ring, so the evened texel averages four radii as well as four turns for no extra
// sample. Each ring's strata are moved on by the golden ratio's fraction from the ring inside it, so
// a texel's turn reads another radius in each ring (a fixed pairing of turn and radius is a spiral:
// docs/quality.md, s27-bounce's "radii paired with the turns"). Only where the tent evens the texels
// out: the refined grid's texels (bounce_refine_gather.comp.glsl) and the light-side entries
// (bounce_entry.frag.glsl) keep their own, un-averaged turn, and the rings read at their middle
// there (BOUNCE_RADIAL_MIDDLE); and only rings 0-2 (bounce.glsl, BOUNCE_STRATIFIED_RINGS). Measured
// against Cycles over four phases of the pattern (docs/quality.md, "Twenty-ninth session: the inner
// rings' radius stratified over the 2 x 2 block"): the ten scenes' mean SSIM +0.00016 (dragon-side
// +0.0012, no scene below -0.0003), within the phases' own swing (0.0007 of the mean); stratified in
// every gather -0.00009 (teapot-back -0.0029), over a 4 x 4 Bayer rank -0.00038 (teapot-back -0.0036,
// dragon-back -0.0019): the pass averages no wider than the 2 x 2 block. Cost +0.01 M instructions of
// the dragon's 800^2 camera frame.
#ifndef BOUNCE_RADIAL_STRATUM_GLSL
#define BOUNCE_RADIAL_STRATUM_GLSL
// bounce_gather's `stratum` for a gather that is not evened out: every ring at its middle, main's
// reading before session 29.
const float BOUNCE_RADIAL_MIDDLE = -1.0;
// texel: the coarse grid's texel (gl_FragCoord). Returns (s + 0.5) / 4, s = 0, 3, 1, 2 for the
// block's texels at turn 0, 1, 2, 3 (bounce_gather.frag.glsl's q.x + 2 q.y).
float bounce_radial_stratum(ivec2 texel) {
  ivec2 q = texel & 1;
  return (float(2 * q.x + (q.x ^ q.y)) + 0.5) / 4.0;
}
#endif
