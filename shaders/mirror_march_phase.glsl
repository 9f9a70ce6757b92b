// Where along its geometric steps the screen-space mirror march (self_reflection.glsl) starts, per
// lighting texel: its first point at SELF_REFLECTION_FIRST x SELF_REFLECTION_GROWTH^phase, every
// later point the same factor on, so `phase` (0 ... 1) slides the whole set of points by a fraction
// of a step. Why: the march's late steps (0.05-0.27 scene units) are longer than a thin part is
// wide, and with one fixed set of points the rays of a whole band of texels step over such a part
// together -- teapot-back's handle arm mirrored in the body beside it, Cycles' one-pixel line of
// glossy indirect light there, was met by 0.19-0.31 of the 800^2 pixels of the line's 200^2 pixels
// (the rest escaped past it), and the picture's SSIM moved 0.9433 ... 0.9485 as one phase for all
// texels went 0 ... 7/8 (docs/quality.md, "Twenty-eighth session: ... the screen march's fixed phase").
// A start stratified over the texels turns that aliasing into a fine dither that the pixel's
// supersamples (and the eye) average: the phase of a 4 x 4 ordered-dither (Bayer) matrix, each of
// the 16 offsets (k + 0.5) / 16 once in every aligned 4 x 4 block of texels, and four far-apart
// ones in every 2 x 2 (Bayer 1973, "An optimum method for two-level rendition of continuous-tone
// pictures"; a jittered start is the usual cure for a screen-space march's banding: McGuire & Mara
// 2014, JCGT 3(4)). Measured against the ten reference scenes (main b3576b8): the mean SSIM
// 0.95562 -> 0.95640, teapot-back +0.0014, bunny-side +0.0024, no scene down more than 0.0001; five
// other stratified or hashed patterns gave +0.00056 ... +0.00073 (the gain is the phase spread, not
// the pattern). At 800^2 without supersampling the mirrored lines show the dither (2 x 2-pixel
// steps of light along them) where a fixed phase showed gaps.
#ifndef MIRROR_MARCH_PHASE_GLSL
#define MIRROR_MARCH_PHASE_GLSL
// texel: the lighting texel (gl_FragCoord of the lighting pass). Returns (k + 0.5) / 16, k the
// texel's rank in the 4 x 4 Bayer matrix: the bits of x and d = x ^ y interleaved, the finest
// (x & 1, d & 1) highest, so that the texels of an aligned 2 x 2 lie a quarter of a step apart.
float mirror_march_phase(ivec2 texel) {
  int x = texel.x, d = texel.x ^ texel.y;
  int k = ((x & 1) << 3) | ((d & 1) << 2) | (x & 2) | ((d >> 1) & 1);
  return (float(k) + 0.5) / 16.0;
}
#endif
