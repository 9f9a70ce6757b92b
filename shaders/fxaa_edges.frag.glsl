#version 450 core
layout(location = 0) out vec4 o_color;
layout(binding = UNIT_SCREEN_INPUT) uniform sampler2D u_image;
uniform vec2 u_texel;
const float kEdgeThreshold = 0.166;
const float kEdgeThresholdMin = 0.0833;
const float kMargin = 1.0 / 1024.0;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 c = texelFetch(u_image, p, 0);
  float m = c.a;
  bool xOdd = (p.x & 1) == 1, yOdd = (p.y & 1) == 1;
  // The corner of the 2x2 quad's outside: the gather holds m, the neighbour outside the quad
  // across x and across y, and the diagonal.
  vec4 g = textureGather(u_image, vec2(p + ivec2(xOdd, yOdd)) * u_texel, 3);
  vec2 rowM = yOdd ? g.wz : g.xy;  // (i0, i1) in m's row
  vec2 colM = xOdd ? g.xw : g.yz;  // (j1, j0) in m's column
  float hOut = xOdd ? rowM.y : rowM.x;
  float vOut = yOdd ? colM.x : colM.y;
  float dx = dFdxFine(m), dy = dFdyFine(m);
  float hIn = xOdd ? m - dx : m + dx;
  float vIn = yOdd ? m - dy : m + dy;
  float maxLuma = max(m, max(max(hOut, vOut), max(hIn, vIn)));
  float minLuma = min(m, min(min(hOut, vOut), min(hIn, vIn)));
  float range = maxLuma - minLuma;
  bool isFlat = range < max(kEdgeThresholdMin, maxLuma * kEdgeThreshold) - kMargin;
  o_color = vec4(c.rgb, 1.0);
  gl_FragDepth = isFlat ? 0.0 : 1.0;
}
