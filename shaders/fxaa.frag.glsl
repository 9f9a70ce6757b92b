#version 450 core
// FXAA, the post-process antialiasing of Timothy Lottes (NVIDIA, "FXAA", white paper 2009, and
// the algorithm of FXAA 3.11's PC "quality" path, 2011), written here from its description. It
// works on the display image (sRGB-encoded, what the viewer sees) and, per pixel:
//   1. takes the luma of the centre and its 4 neighbours; below a local contrast threshold
//      (relative to the brightest of them, with an absolute floor for dark areas) the pixel is
//      "flat" and comes out exactly as it was: flat regions and soft gradients are never touched;
//   2. measures sub-pixel aliasing: the 3x3 low-pass luma against the centre, relative to the
//      contrast (a lone bright pixel or a one-pixel-thin line scores high);
//   3. picks the edge's direction (horizontal or vertical) from second differences of luma over
//      the 3x3 neighbourhood, and its side: the neighbour across it with the steeper gradient;
//   4. walks along the edge in both directions, on the line half a texel toward that side where
//      a bilinear fetch averages both sides, until the luma leaves the edge's average by a
//      quarter of its gradient: the ends of this step of the staircase;
//   5. from the pixel's place on that span: close to the end where the edge steps toward the
//      pixel's side, the true edge crosses the pixel, so it is blended across the edge by up to
//      half a texel (0.5 - distance / span length); at the other end not at all;
//   6. fetches once, bilinearly, moved across the edge by the larger of (5) and (2).
layout(location = 0) out vec4 o_color;
// RGBA8 display image, GL_LINEAR, clamped to edge; alpha: the luma of the colour (the post pass
// computes it once per pixel). Neighbours' lumas are read four at a time (textureGather of
// alpha): on llvmpipe every texture read costs about as much as the rest of a simple pass.
layout(binding = UNIT_SCREEN_INPUT) uniform sampler2D u_image;
uniform vec2 u_texel;                           // 1 / image size

// Lottes' defaults for the quality path: contrast threshold 0.166 (0.063 "overkill" ... 0.333
// "too little"), its absolute floor 0.0833 (0.0312 ... 0.0833), sub-pixel amount 0.75
// (0 off ... 1 softest).
const float kEdgeThreshold = 0.166;
const float kEdgeThresholdMin = 0.0833;
const float kSubpix = 0.75;
// The search's step i along the edge, in texels: exact at first, then longer strides (the ends
// of long, nearly axis-aligned edges are far away), as Lottes' quality presets do. A function, not
// a constant array: llvmpipe indexes arrays lane by lane, which made this pass 3x as slow.
float searchStep(int i) { return i < 4 ? 1.0 : i == 4 ? 1.5 : i < 8 ? 2.0 : i == 8 ? 4.0 : 8.0; }
// How many steps each way (10 reach 23.5 texels; set by FxaaPass). A uniform, not a constant, so
// the compiler cannot unroll the loop: unrolled, llvmpipe runs every step for every pixel under a
// mask (2.5x this pass's cost, measured); a real loop stops when all pixels of a SIMD group are done.
uniform int u_search_steps;

// Luma of the display-referred colour (Rec. 601 weights on the sRGB-encoded values, as FXAA
// expects: perceptual, so thresholds mean the same in dark and bright areas), from alpha.
float lumaAt(vec2 uv) { return textureLod(u_image, uv, 0.0).a; }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 corner = vec2(p) * u_texel;  // the texel's lower-left corner
  // Rows grow upward in GL: "north" is +y. The algorithm is symmetric, the names only help reading.
  // A gather at a texel corner returns the four texels around it as (upper-left, upper-right,
  // lower-right, lower-left); clamping to the edge handles the image border.
  vec4 upperRight = textureGather(u_image, corner + u_texel, 3);          // n, ne, e, m
  vec4 lowerLeft = textureGather(u_image, corner, 3);                     // w, m, s, sw
  vec4 upperLeft = textureGather(u_image, corner + vec2(0.0, u_texel.y), 3);  // nw, n, m, w
  vec4 lowerRight = textureGather(u_image, corner + vec2(u_texel.x, 0.0), 3); // m, e, se, s
  float m = upperRight.w;
  float n = upperRight.x, e = upperRight.z, w = lowerLeft.x, s = lowerLeft.z;

  // 1. Local contrast.
  float maxLuma = max(m, max(max(n, s), max(e, w)));
  float minLuma = min(m, min(min(n, s), min(e, w)));
  float range = maxLuma - minLuma;
  // No early return with the centre's colour: llvmpipe would run the rest under a mask anyway,
  // and a separate read of the centre cost 7 % of this pass (callgrind). A flat pixel takes the
  // final read below at its own centre, which a bilinear fetch returns exactly (weight 1 on the
  // texel); it also ends the edge search at once.
  bool isFlat = range < max(kEdgeThresholdMin, maxLuma * kEdgeThreshold);
  float nw = upperLeft.x, ne = upperRight.y, sw = lowerLeft.w, se = lowerRight.z;

  // 2. Sub-pixel aliasing: tent-weighted 3x3 average (edges 2, corners 1) against the centre;
  // smoothstep and squaring keep it small unless the centre really stands out.
  float lowPass = (2.0 * (n + s + e + w) + (nw + ne + sw + se)) / 12.0;
  float subpix = smoothstep(0.0, 1.0, clamp(abs(lowPass - m) / range, 0.0, 1.0));
  float subpixOffset = subpix * subpix * kSubpix;

  // 3. Direction: a horizontal edge changes luma along y, so the second differences down the
  // three columns are large (weights 1, 2, 1); a vertical edge likewise along the rows.
  float horizontalness = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
  float verticalness = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
  bool horizontal = horizontalness >= verticalness;
  // Across the edge: toward the neighbour with the steeper gradient (one texel, signed).
  float before = horizontal ? s : w, after = horizontal ? n : e;
  float gradBefore = abs(before - m), gradAfter = abs(after - m);
  bool towardBefore = gradBefore >= gradAfter;
  vec2 across = (horizontal ? vec2(0.0, u_texel.y) : vec2(u_texel.x, 0.0)) * (towardBefore ? -1.0 : 1.0);
  vec2 along = horizontal ? vec2(u_texel.x, 0.0) : vec2(0.0, u_texel.y);
  float edgeAverage = 0.5 * (m + (towardBefore ? before : after));
  float endThreshold = 0.25 * max(gradBefore, gradAfter);

  // 4. Search both ways along the line between the two sides of the edge.
  vec2 uv = (vec2(p) + 0.5) * u_texel;
  vec2 onEdge = uv + 0.5 * across;
  vec2 uvBack = onEdge, uvFore = onEdge;
  float endBack = 0.0, endFore = 0.0;
  bool doneBack = isFlat, doneFore = isFlat;
  for (int i = 0; i < u_search_steps && !(doneBack && doneFore); ++i) {
    if (!doneBack) {
      uvBack -= along * searchStep(i);
      endBack = lumaAt(uvBack) - edgeAverage;
      doneBack = abs(endBack) >= endThreshold;
    }
    if (!doneFore) {
      uvFore += along * searchStep(i);
      endFore = lumaAt(uvFore) - edgeAverage;
      doneFore = abs(endFore) >= endThreshold;
    }
  }

  // 5. Where on the span the pixel lies. At the nearer end the luma must leave the edge's
  // average the other way than the centre does (the staircase steps toward this pixel's side);
  // otherwise the edge is not crossing this pixel and only the sub-pixel term applies.
  float distBack = horizontal ? uv.x - uvBack.x : uv.y - uvBack.y;
  float distFore = horizontal ? uvFore.x - uv.x : uvFore.y - uv.y;
  bool backNearer = distBack < distFore;
  float nearEnd = backNearer ? endBack : endFore;
  bool crossesHere = (nearEnd < 0.0) != (m - edgeAverage < 0.0);
  float edgeOffset = crossesHere ? 0.5 - min(distBack, distFore) / (distBack + distFore) : 0.0;

  // 6. One bilinear fetch, moved across the edge (a flat pixel: not moved).
  float offset = isFlat ? 0.0 : max(edgeOffset, subpixOffset);
  o_color = vec4(textureLod(u_image, uv + offset * across, 0.0).rgb, 1.0);
}
