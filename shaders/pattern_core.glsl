// The marble pattern (paper §3.1): ONE SOURCE for the GPU and the C++ reference.
//
// This file is compiled twice:
//   * as GLSL 4.50, included into marble_pattern.glsl (which adds the u_pat_ uniforms);
//   * as C++20, #included by src/marble/noise/marble_pattern.cpp inside a namespace that says
//     `using namespace glm; using uint = uint32_t;` (GLM mirrors GLSL's vocabulary).
// So it is written in the subset both languages accept: float/vec2/vec3/uint/int, a plain
// struct (built by each side, never constructed here), floor/fract/abs/sin/pow/min/max,
// `f`-suffixed float literals (GLSL 4.50 accepts them; in C++ they keep all arithmetic in
// float, so both sides compute in single precision), `u`-suffixed uint literals, no swizzles
// (GLM is built with GLM_FORCE_XYZW_ONLY), no in/out/inout qualifiers, no arrays, no
// preprocessor lines. No uniforms here: every function takes its parameters explicitly.
//
// Stages and conventions (Lode Vandevenne's texture tutorial, as the paper uses it):
//   white noise   : a value in [0,1) per lattice cell; here an integer hash of the cell, so the
//                   same bits come out on CPU and GPU (no rand(), no texture upload).
//   smooth noise  : the lattice interpolated linearly (Lode: bilinear, no fade curve), or
//                   Perlin's improved gradient noise (2002) mapped to [0,1].
//   turbulence    : sum over size = turbSize, size /= 2 while size >= 1 of
//                   smooth(q / size) * size, divided by 2 * turbSize  -> [0,1)
//                   (q / size computed as q * (1 / size), the reciprocal doubling per octave:
//                   exact for power-of-two sizes, and a division per point saved)
//                   (Lode's 128 * sum / turbSize is this times 256).
//   sine pattern  : |sin(pi * (x*xPeriod/W + y*yPeriod/H + turbPower * turbulence))|
//                   (the paper's turbPower * turbulence / 256 with turbulence in [0,256)).
// Coordinates q are in texels of the W x W texture (W = resolution). The lattice of the
// octave of size s has period W/s cells, so every octave, hence the turbulence, wraps with
// period W texels: the texture tiles seamlessly (exact when s divides W, e.g. powers of two).
// Lode interpolates a cell between lattice points i-1 and i; we use i and i+1 (the same
// pattern shifted by one texel).

const float PAT_PI = 3.14159265358979f;

const int PAT_BASIS_VALUE = 0;
const int PAT_BASIS_PERLIN = 1;
const int PAT_MAP_PLANAR = 0;
const int PAT_MAP_TRIPLANAR = 1;
const int PAT_MAP_SOLID = 2;

struct PatParams {
  uint seed;          // white-noise lattice seed
  float resolution;   // W = H in texels
  int basis;          // PAT_BASIS_*
  int mapping;        // PAT_MAP_*
  vec3 period;        // x_period, y_period, z_period
  float turbPower;    // 0: plain sine
  float turbSize;     // first octave size in texels
  float scale;        // object units per half texture width
  float sharpness;    // vein sharpness (1 = the paper)
  float vein2Amount;  // 0 = two-colour ramp (the paper)
  vec3 baseColor;
  vec3 veinColor;
  vec3 vein2Color;
  // --- vein model (issue 16): read only when veinModel != PAT_VEINS_PAPER ---
  int veinModel;      // PAT_VEINS_*
  vec3 veinSpacing;   // dominant, secondary, hairline: mean distance between cracks, object units
  vec3 veinWidth;     // full width of each family's veins, object units
  vec3 veinDensity;   // fraction of each family's cracks that are filled, [0,1]
  vec3 veinNormal;   // unit: the normal of the planes the dominant veins lie in (bedding)
  float veinStretch;  // how much thinner the dominant cells are across veinNormal (>= 1)
  float veinWarp;     // domain-warp amplitude, object units
  float veinPinch;    // [0,1]: how much a vein's width swells and pinches (1: down to nothing)
  float veinSoftness; // [0,1]: edge blur relative to the width
  vec3 vein3Color;    // hairline veins
  vec3 cloudColor;    // the ground's clouds (nuvolato)
  float cloudAmount;  // [0,1]
  float grainAmount;  // [0,1]: contrast of the fine calcite grain
  float fragmentTint; // [0,1], breccia: how much fragments differ in colour
  float fragmentSplit; // [0,1], breccia: probability that a fragment is broken again at the next finer spacing
};

// ---- white noise ------------------------------------------------------------------------

// Chris Wellons' "lowbias32" integer hash (public domain): 32-bit multiply/xor/shift only.
uint pat_hash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

// Top 24 bits -> [0,1), exactly representable in float.
float pat_unit(uint h) { return float(h >> 8u) * (1.0f / 16777216.0f); }

// i mod period for integer-valued floats, exact (the correction steps absorb a division
// that rounds the quotient across an integer).
float pat_wrap(float i, float period) {
  if (i >= 0.0f && i < period) return i;  // the common case, without the division
  float w = i - period * floor(i / period);
  if (w >= period) w -= period;
  if (w < 0.0f) w += period;
  return w;
}

// Lattice period (cells) of the octave whose cells are 1/inv texels, in a texture of `res` texels.
float pat_octave_period(float res, float inv) { return max(1.0f, floor(res * inv + 0.5f)); }

float pat_lerp(float a, float b, float t) { return a + (b - a) * t; }

// A lattice point's hash: lowbias32 of x*K1 + y*K2 + z*K3 + hash(seed) (odd constants: a
// bijection in each coordinate), one hash per corner. The (y, z) part is a separate function so
// a row of points (fixed y, z) computes it once.
uint pat_hash_yz(float y, float z, uint seedHash) { return uint(y) * 0xd8163841u + uint(z) * 0xcb1ab31fu + seedHash; }
uint pat_hash_y(float y, uint seedHash) { return uint(y) * 0xd8163841u + seedHash; }
uint pat_hash_x(float x, uint hyz) { return pat_hash(uint(x) * 0x8da6b343u + hyz); }

// The lattice index after w (already wrapped), wrapped.
float pat_next(float w, float period) { return w + 1.0f >= period ? 0.0f : w + 1.0f; }

// White noise at integer lattice point (wrapped with `period`), 2D and 3D.
float pat_white2(vec2 cell, float period, uint seedHash) {
  return pat_unit(pat_hash_x(pat_wrap(cell.x, period), pat_hash_y(pat_wrap(cell.y, period), seedHash)));
}
float pat_white3(vec3 cell, float period, uint seedHash) {
  return pat_unit(pat_hash_x(pat_wrap(cell.x, period),
                             pat_hash_yz(pat_wrap(cell.y, period), pat_wrap(cell.z, period), seedHash)));
}

// ---- smooth noise: value (the paper's) ---------------------------------------------------

// Value noise at lattice column x (already wrapped), interpolated over y (and z) first:
// h0/h1 are the row hashes at y0/y1 (2D), or h00,h10,h01,h11 at (y0,z0),(y1,z0),(y0,z1),(y1,z1).
float pat_value2_column(float x, uint h0, uint h1, float fy) {
  return pat_lerp(pat_unit(pat_hash_x(x, h0)), pat_unit(pat_hash_x(x, h1)), fy);
}
float pat_value3_column(float x, uint h00, uint h10, uint h01, uint h11, float fy, float fz) {
  float a = pat_lerp(pat_unit(pat_hash_x(x, h00)), pat_unit(pat_hash_x(x, h10)), fy);
  float b = pat_lerp(pat_unit(pat_hash_x(x, h01)), pat_unit(pat_hash_x(x, h11)), fy);
  return pat_lerp(a, b, fz);
}

// p in lattice units; result in [0,1].
float pat_value2(vec2 p, float period, uint seedHash) {
  vec2 i = floor(p);
  vec2 f = p - i;
  float x0 = pat_wrap(i.x, period);
  float y0 = pat_wrap(i.y, period);
  uint h0 = pat_hash_y(y0, seedHash);
  uint h1 = pat_hash_y(pat_next(y0, period), seedHash);
  return pat_lerp(pat_value2_column(x0, h0, h1, f.y), pat_value2_column(pat_next(x0, period), h0, h1, f.y), f.x);
}
float pat_value3(vec3 p, float period, uint seedHash) {
  vec3 i = floor(p);
  vec3 f = p - i;
  float y0 = pat_wrap(i.y, period);
  float y1 = pat_next(y0, period);
  float z0 = pat_wrap(i.z, period);
  float z1 = pat_next(z0, period);
  uint h00 = pat_hash_yz(y0, z0, seedHash);
  uint h10 = pat_hash_yz(y1, z0, seedHash);
  uint h01 = pat_hash_yz(y0, z1, seedHash);
  uint h11 = pat_hash_yz(y1, z1, seedHash);
  float x0 = pat_wrap(i.x, period);
  return pat_lerp(pat_value3_column(x0, h00, h10, h01, h11, f.y, f.z),
                  pat_value3_column(pat_next(x0, period), h00, h10, h01, h11, f.y, f.z), f.x);
}

// The grain: one octave of value noise on a lattice of period 2^20, pat_value3(p, 2^20, seedHash)
// bit for bit for lattice indices in [-2^20, 2^20) (the Voronoi search's range too), without
// pat_wrap's division and corrections (a GPU runs those on every point: llvmpipe executes both
// sides of its early return): the index plus 2^20 is an exact integer float there, and its low
// 20 bits are the wrapped index.
float pat_grain(vec3 p, uint seedHash) {
  vec3 i = floor(p);
  vec3 f = p - i;
  uint x0 = uint(i.x + 1048576.0f) & 1048575u;
  uint y0 = uint(i.y + 1048576.0f) & 1048575u;
  uint z0 = uint(i.z + 1048576.0f) & 1048575u;
  uint x1 = (x0 + 1u) & 1048575u;
  uint y1 = (y0 + 1u) & 1048575u;
  uint z1 = (z0 + 1u) & 1048575u;
  // pat_hash_yz and pat_value3_column's sums and lerps, in their order.
  uint h00 = y0 * 0xd8163841u + z0 * 0xcb1ab31fu + seedHash;
  uint h10 = y1 * 0xd8163841u + z0 * 0xcb1ab31fu + seedHash;
  uint h01 = y0 * 0xd8163841u + z1 * 0xcb1ab31fu + seedHash;
  uint h11 = y1 * 0xd8163841u + z1 * 0xcb1ab31fu + seedHash;
  uint a = x0 * 0x8da6b343u;
  uint b = x1 * 0x8da6b343u;
  float c0 = pat_lerp(pat_lerp(pat_unit(pat_hash(a + h00)), pat_unit(pat_hash(a + h10)), f.y),
                      pat_lerp(pat_unit(pat_hash(a + h01)), pat_unit(pat_hash(a + h11)), f.y), f.z);
  float c1 = pat_lerp(pat_lerp(pat_unit(pat_hash(b + h00)), pat_unit(pat_hash(b + h10)), f.y),
                      pat_lerp(pat_unit(pat_hash(b + h01)), pat_unit(pat_hash(b + h11)), f.y), f.z);
  return pat_lerp(c0, c1, f.x);
}

// ---- smooth noise: Perlin's improved noise (Perlin 2002) ----------------------------------
// Same algorithm (quintic fade, the 12 edge gradients of a cube picked by 4 hash bits), with the
// integer hash in place of the permutation table so the lattice wraps with any period.

float pat_fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// Perlin's grad(): u = k < 8 ? x : y; v = k < 4 ? y : (k == 12 || k == 14 ? x : z); signs from
// bits 0 and 1. Written with 0/1 weights instead of branches (hash bits are unpredictable, so
// branches mispredict on the CPU); a product with 0 or 1 and a sum with 0 are exact, so the
// value is the same.
float pat_grad(uint h, float x, float y, float z) {
  uint k = (h >> 4u) & 15u;
  float a = float(k < 8u);
  float b = float(k < 4u);
  float c = float(k == 12u || k == 14u);
  float u = x * a + y * (1.0f - a);
  float v = y * b + (x * c + z * (1.0f - c)) * (1.0f - b);
  return u * (1.0f - float(k & 1u) * 2.0f) + v * (1.0f - float(k & 2u));
}

// In [-1,1]; the 2D version is the z = 0 slice of the 3D one.
float pat_perlin2_signed(vec2 p, float period, uint seedHash) {
  vec2 i = floor(p);
  vec2 f = p - i;
  float x0 = pat_wrap(i.x, period);
  float x1 = pat_next(x0, period);
  float y0 = pat_wrap(i.y, period);
  uint h0 = pat_hash_y(y0, seedHash);
  uint h1 = pat_hash_y(pat_next(y0, period), seedHash);
  float u = pat_fade(f.x);
  float v = pat_fade(f.y);
  float a = pat_lerp(pat_grad(pat_hash_x(x0, h0), f.x, f.y, 0.0f), pat_grad(pat_hash_x(x1, h0), f.x - 1.0f, f.y, 0.0f), u);
  float b = pat_lerp(pat_grad(pat_hash_x(x0, h1), f.x, f.y - 1.0f, 0.0f),
                     pat_grad(pat_hash_x(x1, h1), f.x - 1.0f, f.y - 1.0f, 0.0f), u);
  return pat_lerp(a, b, v);
}
float pat_perlin3_signed(vec3 p, float period, uint seedHash) {
  vec3 i = floor(p);
  vec3 f = p - i;
  float x0 = pat_wrap(i.x, period);
  float x1 = pat_next(x0, period);
  float y0 = pat_wrap(i.y, period);
  float y1 = pat_next(y0, period);
  float z0 = pat_wrap(i.z, period);
  float z1 = pat_next(z0, period);
  uint h00 = pat_hash_yz(y0, z0, seedHash);
  uint h10 = pat_hash_yz(y1, z0, seedHash);
  uint h01 = pat_hash_yz(y0, z1, seedHash);
  uint h11 = pat_hash_yz(y1, z1, seedHash);
  float u = pat_fade(f.x);
  float v = pat_fade(f.y);
  float w = pat_fade(f.z);
  float gx = f.x - 1.0f;
  float gy = f.y - 1.0f;
  float gz = f.z - 1.0f;
  float a0 = pat_lerp(pat_grad(pat_hash_x(x0, h00), f.x, f.y, f.z), pat_grad(pat_hash_x(x1, h00), gx, f.y, f.z), u);
  float a1 = pat_lerp(pat_grad(pat_hash_x(x0, h10), f.x, gy, f.z), pat_grad(pat_hash_x(x1, h10), gx, gy, f.z), u);
  float b0 = pat_lerp(pat_grad(pat_hash_x(x0, h01), f.x, f.y, gz), pat_grad(pat_hash_x(x1, h01), gx, f.y, gz), u);
  float b1 = pat_lerp(pat_grad(pat_hash_x(x0, h11), f.x, gy, gz), pat_grad(pat_hash_x(x1, h11), gx, gy, gz), u);
  return pat_lerp(pat_lerp(a0, a1, v), pat_lerp(b0, b1, v), w);
}

// Smooth noise in [0,1] for either basis.
float pat_smooth2(vec2 p, float period, uint seedHash, int basis) {
  if (basis == PAT_BASIS_PERLIN) return min(max(0.5f + 0.5f * pat_perlin2_signed(p, period, seedHash), 0.0f), 1.0f);
  return pat_value2(p, period, seedHash);
}
float pat_smooth3(vec3 p, float period, uint seedHash, int basis) {
  if (basis == PAT_BASIS_PERLIN) return min(max(0.5f + 0.5f * pat_perlin3_signed(p, period, seedHash), 0.0f), 1.0f);
  return pat_value3(p, period, seedHash);
}

// ---- turbulence and the sine pattern -------------------------------------------------------

// q in texels; result in [0,1).
float pat_turbulence2(PatParams P, vec2 q) {
  uint sh = pat_hash(P.seed);
  float sum = 0.0f;
  for (float size = P.turbSize, inv = 1.0f / P.turbSize; size >= 1.0f; size *= 0.5f, inv *= 2.0f)
    sum += pat_smooth2(q * inv, pat_octave_period(P.resolution, inv), sh, P.basis) * size;
  return sum / (2.0f * P.turbSize);
}
float pat_turbulence3(PatParams P, vec3 q) {
  uint sh = pat_hash(P.seed);
  float sum = 0.0f;
  for (float size = P.turbSize, inv = 1.0f / P.turbSize; size >= 1.0f; size *= 0.5f, inv *= 2.0f)
    sum += pat_smooth3(q * inv, pat_octave_period(P.resolution, inv), sh, P.basis) * size;
  return sum / (2.0f * P.turbSize);
}

// ramp: pat_ramp2/3 below; turbulence in [0,1). Result in [0,1].
float pat_sine(float ramp, float turbulence, float turbPower) {
  return abs(sin(PAT_PI * (ramp + turbPower * turbulence)));
}

// The sine's linear part: x*xPeriod/W + y*yPeriod/H (+ z*zPeriod/W).
float pat_ramp2(PatParams P, vec2 q) { return (q.x * P.period.x + q.y * P.period.y) / P.resolution; }
float pat_ramp3(PatParams P, vec3 q) { return (q.x * P.period.x + q.y * P.period.y + q.z * P.period.z) / P.resolution; }

// The paper's 2D texture at texel q (s along x, t along y).
float pat_pattern2(PatParams P, vec2 q) { return pat_sine(pat_ramp2(P, q), pat_turbulence2(P, q), P.turbPower); }
// Solid marble at texel-space point q.
float pat_pattern3(PatParams P, vec3 q) { return pat_sine(pat_ramp3(P, q), pat_turbulence3(P, q), P.turbPower); }

// ---- mappings ----------------------------------------------------------------------------

// Object units -> texels: pattern_scale object units per half texture width.
vec3 pat_texel_pos(PatParams P, vec3 objectPos) { return objectPos * (0.5f * P.resolution / P.scale); }

// GL_MIRRORED_REPEAT on texel coordinates: identity on [0,W], W - (s - W) on [W,2W], -s on
// [-W,0], period 2W. Continuous; result in [0,W].
float pat_mirror(float s, float W) {
  float m = s - 2.0f * W * floor(s / (2.0f * W));
  return W - abs(m - W);
}

// The paper's planar mapping: s, t from object x, z; constant along y (stretch), mirrored
// beyond the bounds.
vec2 pat_planar_texel(PatParams P, vec3 q) { return vec2(pat_mirror(q.x, P.resolution), pat_mirror(q.z, P.resolution)); }

// Triplanar: three planar projections (no mirroring; the texture tiles) blended by the
// normal's components to the 4th power. Planes (z, y), (x, z), (x, y) take w.x, w.y, w.z.
vec3 pat_triplanar_weights(vec3 objectNormal) {
  vec3 w = abs(objectNormal);
  w = w * w;
  w = w * w;
  return w / max(w.x + w.y + w.z, 1e-20f);
}

// The three planes' values (zy, xz, xy) blended by pat_triplanar_weights.
float pat_triplanar_mix(vec3 w, float zy, float xz, float xy) { return w.x * zy + w.y * xz + w.z * xy; }

// Value before colouring, in [0,1]. (marble_pattern.glsl repeats this dispatch once, with the
// turbulence read from its baked grid instead of evaluated.)
float pat_value_at(PatParams P, vec3 objectPos, vec3 objectNormal) {
  vec3 q = pat_texel_pos(P, objectPos);
  if (P.mapping == PAT_MAP_SOLID) return pat_pattern3(P, q);
  if (P.mapping == PAT_MAP_PLANAR) return pat_pattern2(P, pat_planar_texel(P, q));
  return pat_triplanar_mix(pat_triplanar_weights(objectNormal), pat_pattern2(P, vec2(q.z, q.y)),
                           pat_pattern2(P, vec2(q.x, q.z)), pat_pattern2(P, vec2(q.x, q.y)));
}

// ---- colour ramp ----------------------------------------------------------------------------

// v = 0 is the heart of a vein, v = 1 the stone between veins. Sharpness s applies v^(1/s):
// s > 1 thins the veins, s < 1 widens them. The ramp is vein -> base (the paper), blended
// with vein -> vein2 -> base (vein2 at the middle) by vein2Amount.
// a*(1-t) + b*t: exactly a at t = 0 and exactly b at t = 1.
vec3 pat_mix3(vec3 a, vec3 b, float t) { return a * (1.0f - t) + b * t; }

vec3 pat_color(PatParams P, float v) {
  float t = pow(min(max(v, 0.0f), 1.0f), 1.0f / P.sharpness);
  vec3 two = pat_mix3(P.veinColor, P.baseColor, t);
  vec3 three = t < 0.5f ? pat_mix3(P.veinColor, P.vein2Color, 2.0f * t) : pat_mix3(P.vein2Color, P.baseColor, 2.0f * t - 1.0f);
  return pat_mix3(two, three, P.vein2Amount);
}

vec3 pat_albedo(PatParams P, vec3 objectPos, vec3 objectNormal) {
  return pat_color(P, pat_value_at(P, objectPos, objectNormal));
}

// ---- vein networks (issue 16): marble as mineral-filled fractures ---------------------------
//
// Real veins are cracks filled with other minerals, so they form networks: they fork, rejoin,
// end against each other, swell and pinch. The model, in object space (solid, no seams):
//   * the crack network of one family is the set of faces of a 3D Voronoi diagram (Worley,
//     "A Cellular Texture Basis Function", SIGGRAPH 1996): points where the distances to the
//     nearest and second-nearest feature points are close (within width/2 of their bisecting
//     plane: the exact distance, not F2 - F1, which widens where two points nearly coincide). Voronoi faces meet
//     three at an edge, so in any slice veins meet at Y junctions -- the forks of real marble;
//   * the space is domain-warped first (Quilez, "Domain warping", 2002/2012): p + a * (T - 0.5)
//     with T three samples of the paper's turbulence (its octaves down to 2 texels), so the faces meander like veins instead
//     of being flat; the space is also stretched along the veins' normal, so cells are
//     flattened and the dominant veins lie roughly in one family of planes;
//   * each face (a pair of cells) is filled or not by a hash of the pair (density: the fraction
//     of cracks that are filled), and its width follows a fourth turbulence sample, so veins
//     swell, pinch and fade out inside the stone;
//   * three families at different spacings (dominant, secondary, hairline) are composed from
//     the finest to the coarsest over a cloudy ground with fine grain;
//   * breccia: angular fragments of three sizes in a matrix, cut by cracks (see "breccia" below).
// Voronoi search: the 2 x 2 x 2 cells nearest the point (not 3 x 3 x 3), with feature points
// jittered over the central 80 % of their cells. This is exact for F1 almost everywhere and
// rarely picks a wrong F2 (a short straight cut in a vein where it does, hidden by the warp);
// it costs 8 cells instead of 27, which is what fits the frame budget.

const int PAT_VEINS_PAPER = 0;
const int PAT_VEINS_NETWORK = 1;
const int PAT_VEINS_BRECCIA = 2;

// The result of one Voronoi search: the two nearest distances and their cells' hashes.
struct PatCells {
  float f1;  // squared distances while searching
  float f2;
  uint h1;
  uint h2;
  vec3 v1;   // from the point to the nearest and second-nearest feature points
  vec3 v2;
  float edge;  // twice the distance to the face between the two nearest cells (cell units)
};

// The two nearest of a Voronoi search so far, updated with one more cell (squared distance d,
// hash h, corner k: which of the block's 8 cells): strict `<`, so of equal distances the
// earlier cell stays first. Written as selects and mins, not as `if (d < f1) ... else if (d <
// f2)`: the same values (where d is not the nearest, the second is min(d, f2), its hash and
// corner replaced only if d is strictly nearer; an equal distance keeps the value it had), with
// fewer operations where the lanes of a SIMD unit take different sides (llvmpipe runs both).
// The offsets to the two feature points are rebuilt from hash and corner once the search is
// done (pat_voronoi): a corner is one select per step where an offset is three.
struct PatNearest {
  float f1;
  float f2;
  uint h1;
  uint h2;
  uint k1;
  uint k2;
};
PatNearest pat_cells_insert(PatNearest c, float d, uint h, uint k) {
  bool first = d < c.f1;
  bool second = d < c.f2;
  c.f2 = first ? c.f1 : min(d, c.f2);
  c.h2 = first ? c.h1 : (second ? h : c.h2);
  c.k2 = first ? c.k1 : (second ? k : c.k2);
  c.f1 = min(d, c.f1);
  c.h1 = first ? h : c.h1;
  c.k1 = first ? k : c.k1;
  return c;
}

// The feature points are jittered over the central 80 % of their cells: 0.1 + 0.8 j / 1024 along
// each axis for a 10-bit j. The step 0.8 / 1024 (the float nearest 0.8f / 1024, which scaling
// by a power of two leaves exact).
const float PAT_JITTER_STEP = 0.00078125f;

// The offset from the point to the feature point of a cell with hash h, given per axis the
// offset from the point to the cell's corner plus 0.1 (o = cell corner + 0.1 - point): three
// 10-bit jitters, one multiply-add each.
vec3 pat_cell_offset(uint h, float ox, float oy, float oz) {
  return vec3(ox + float(h & 1023u) * PAT_JITTER_STEP, oy + float((h >> 10u) & 1023u) * PAT_JITTER_STEP,
              oz + float((h >> 20u) & 1023u) * PAT_JITTER_STEP);
}

// |v|^2 summed in the search's order.
float pat_sq(vec3 v) { return v.x * v.x + v.y * v.y + v.z * v.z; }

// 3D Voronoi F1/F2 at p (cell units), feature points from the cell hash; `salt` picks the family.
PatCells pat_voronoi(vec3 p, uint salt) {
  vec3 i = floor(p);
  vec3 f = p - i;
  // The 2x2x2 block of cells nearest p: from i or i-1 along each axis.
  float bx = f.x < 0.5f ? -1.0f : 0.0f;
  float by = f.y < 0.5f ? -1.0f : 0.0f;
  float bz = f.z < 0.5f ? -1.0f : 0.0f;
  // Per axis, the offset from the point to the lower and the upper cell's corner plus 0.1 (the
  // jitter's start): computed once, not per cell.
  float ax = bx + 0.1f - f.x;
  float ay = by + 0.1f - f.y;
  float az = bz + 0.1f - f.z;
  float cx = ax + 1.0f;
  float cy = ay + 1.0f;
  float cz = az + 1.0f;
  // A cell's hash is lowbias32 of x*K1 + y*K2 + z*K3 + salt over its integer coordinates
  // (offset by 2^20 so negative cells hash as distinct uints): the sum mod 2^32 is computed
  // from one product per axis, the block's upper cell adding K (the coordinates are integers
  // below 2^24, exact in float, so this is the per-cell product's value).
  uint x0 = uint(i.x + bx + 1048576.0f) * 0x8da6b343u;
  uint x1 = x0 + 0x8da6b343u;
  uint y0 = uint(i.y + by + 1048576.0f) * 0xd8163841u;
  uint y1 = y0 + 0xd8163841u;
  uint z0 = uint(i.z + bz + 1048576.0f) * 0xcb1ab31fu + salt;
  uint z1 = z0 + 0xcb1ab31fu;
  // The eight cells in the order x fastest, then y, then z (which of equal distances wins);
  // corner k: bit 0 the upper x, bit 1 the upper y, bit 2 the upper z.
  uint h0 = pat_hash(x0 + y0 + z0);
  uint h1 = pat_hash(x1 + y0 + z0);
  float d0 = pat_sq(pat_cell_offset(h0, ax, ay, az));
  float d1 = pat_sq(pat_cell_offset(h1, cx, ay, az));
  // The first two cells sorted: what inserting them into an empty pair (distances 1e9) gives,
  // as a squared distance here is at most 3 * 1.9^2 and the second is always kept.
  PatNearest n;
  bool swap = d1 < d0;
  n.f1 = swap ? d1 : d0;
  n.h1 = swap ? h1 : h0;
  n.k1 = swap ? 1u : 0u;
  n.f2 = swap ? d0 : d1;
  n.h2 = swap ? h0 : h1;
  n.k2 = swap ? 0u : 1u;
  uint h = pat_hash(x0 + y1 + z0);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, ax, cy, az)), h, 2u);
  h = pat_hash(x1 + y1 + z0);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, cx, cy, az)), h, 3u);
  h = pat_hash(x0 + y0 + z1);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, ax, ay, cz)), h, 4u);
  h = pat_hash(x1 + y0 + z1);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, cx, ay, cz)), h, 5u);
  h = pat_hash(x0 + y1 + z1);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, ax, cy, cz)), h, 6u);
  h = pat_hash(x1 + y1 + z1);
  n = pat_cells_insert(n, pat_sq(pat_cell_offset(h, cx, cy, cz)), h, 7u);
  // The two nearest cells' offsets, rebuilt from hash and corner: the values the search summed.
  PatCells c;
  c.f1 = n.f1;
  c.f2 = n.f2;
  c.h1 = n.h1;
  c.h2 = n.h2;
  c.v1 = pat_cell_offset(n.h1, (n.k1 & 1u) == 1u ? cx : ax, (n.k1 & 2u) == 2u ? cy : ay, (n.k1 & 4u) == 4u ? cz : az);
  c.v2 = pat_cell_offset(n.h2, (n.k2 & 1u) == 1u ? cx : ax, (n.k2 & 2u) == 2u ? cy : ay, (n.k2 & 4u) == 4u ? cz : az);
  // The distance to the bisecting plane of the two nearest feature points, (F2^2 - F1^2) /
  // (2 |v2 - v1|): unlike F2 - F1 it does not widen where the two points are close together.
  vec3 dv = c.v2 - c.v1;
  c.edge = (c.f2 - c.f1) / max(sqrt(dot(dv, dv)), 1e-6f);
  c.f1 = sqrt(c.f1);
  c.f2 = sqrt(c.f2);
  return c;
}


// 1 at the heart of a vein of full width w (object units) at e = twice the distance to its
// crack (PatCells.edge, in object units), 0 outside, a smooth edge of relative width `soft`.
float pat_vein_cover(float e, float w, float soft) {
  float lo = w * (1.0f - soft);
  float hi = w * (1.0f + soft) + 1e-6f;
  float t = min(max((hi - e) / (hi - lo), 0.0f), 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// A face's fill in [0,1): symmetric in the two cells, so the face is one crack.
float pat_face_random(PatCells c) { return pat_unit(pat_hash((c.h1 ^ c.h2) + 0x68e31da4u)); }

// Expands p along the unit normal n by `stretch`: cells become `stretch` times thinner along n,
// so most of their faces (the veins) are sheets across n -- veins that lie in one family of
// planes, as in a stone whose fractures follow its bedding. A cut across n shows them as
// roughly parallel lines; a cut along n (a "fleuri" cut, in the trade) shows broad clouds.
vec3 pat_stretch(vec3 p, vec3 n, float stretch) { return p + n * (dot(p, n) * (stretch - 1.0f)); }

// The vein model's turbulence: the paper's octaves (turbSize, turbSize/2, ...) down to 2
// texels instead of 1, normalized by their weights to [0,1] (mean 0.5). The finest octave adds
// only 1/(2 turbSize) of the amplitude to a warp or a width, invisible there; without it the
// turbulence is multilinear on 2-texel cells, so the four samples below fit one grid of
// (W/2)^3 four-channel texels, read with one filtered fetch (noise/turbulence_grid.h).
float pat_vein_min_octave(PatParams P) { return min(2.0f, P.turbSize); }
float pat_vein_turbulence3(PatParams P, vec3 q) {
  uint sh = pat_hash(P.seed);
  float sum = 0.0f;
  float weight = 0.0f;
  for (float size = P.turbSize, inv = 1.0f / P.turbSize; size >= pat_vein_min_octave(P); size *= 0.5f, inv *= 2.0f) {
    sum += pat_smooth3(q * inv, pat_octave_period(P.resolution, inv), sh, P.basis) * size;
    weight += size;
  }
  return sum / weight;
}

// The texel offset of the vein model's turbulence sample k (0-2 the warp, 3 the width field):
// fractions of the period W so the samples are independent (the turbulence wraps with period
// W), rounded to even texels so that the grid's texel i holds all four at the texel points
// 2i + offset (one fetch for the four).
vec3 pat_vein_sample_offset(PatParams P, int k) {
  float h = 0.5f * P.resolution;
  if (k == 1) return 2.0f * floor(vec3(0.31f * h, 0.57f * h, 0.13f * h));
  if (k == 2) return 2.0f * floor(vec3(0.71f * h, 0.19f * h, 0.43f * h));
  if (k == 3) return 2.0f * floor(vec3(0.47f * h, 0.83f * h, 0.67f * h));
  return vec3(0.0f);
}

// The texel-space point of the vein model's turbulence sample k at object point p.
vec3 pat_vein_sample_point(PatParams P, vec3 objectPos, int k) {
  return pat_texel_pos(P, objectPos) + pat_vein_sample_offset(P, k);
}

// ---- veins seen through the polish (issue 16: the vein colour is absorption inside the stone) ----
// The colour seen at a surface point is the stone's along the refracted view ray, weighted by
// how much of the light that leaves there has been at each depth d: in the diffusion regime
// the fluence falls as exp(-sigma_tr d), sigma_tr = sqrt(3 sigma_a sigma_t') (Jensen et al.
// 2001, "A Practical Model for Subsurface Light Transport", sec. 2.4), so at distance t along a
// ray at cos(theta_t) to the normal the weight is k exp(-k t), k = sigma_tr cos(theta_t) (per
// object unit: the caller converts with mm_per_unit). Each family's nearest crack is taken as
// the plane it is at the surface point (the warp's curvature over the depth 1/k neglected):
// along the ray twice the distance to it is e0 + b t, with b = -2 S(ray).n (n the unit normal
// of the face between the two nearest cells, S the family's stretch), so the part of the ray
// inside a vein of full width w is the interval where |e0 + b t| < w, and its weight is
// exp(-k t_lo) - exp(-k t_hi), exactly. The vein at the surface keeps its own (crisp) cover;
// the seen cover is the larger of the two, so veins just under the polish show as soft
// shadows on the side they dip to, fading with depth. Valid while 1/k is small against the
// family's spacing (the nearest face is the only one the ray meets; beyond a quarter spacing
// from the crack the buried part is faded out, see pat_cells_cover); k = 0: the surface only.
float pat_vein_depth_cover(float e0, float b, float w, float k) {
  if (abs(b) < 1e-6f) return e0 < w ? 1.0f : 0.0f;  // along the crack: inside it all the way, or never
  float ta = (-w - e0) / b;
  float tb = (w - e0) / b;
  float lo = max(min(ta, tb), 0.0f);
  float hi = max(ta, tb);
  if (hi <= lo) return 0.0f;
  return exp(-k * lo) - exp(-k * hi);
}

// The cover of the vein of full width `width` on the face of cells c (spacing, stretch as the
// family's), at the surface, or seen along `ray` with attenuation k (k > 0).
float pat_cells_cover(PatParams P, PatCells c, float spacing, float stretch, float width, vec3 ray, float k) {
  float e0 = c.edge * spacing;
  float cover = pat_vein_cover(e0, width, P.veinSoftness);
  if (k <= 0.0f || width <= 0.0f) return cover;
  vec3 dv = c.v2 - c.v1;
  float b = -2.0f * dot(pat_stretch(ray, P.veinNormal, stretch), dv) / max(sqrt(dot(dv, dv)), 1e-6f);
  // Beyond a quarter of the spacing from the crack the face between the two nearest cells
  // stops being the one a ray meets first (the nearest pair changes there, with a straight
  // seam): the buried part fades out before that.
  float reach = min(max(1.0f - e0 / (0.25f * spacing), 0.0f), 1.0f);
  return max(cover, reach * reach * pat_vein_depth_cover(e0, b, width, k));
}

// One family's coverage at warped point p: `spacing` apart, `stretch` along d, width w,
// `density` of faces filled, width modulated by m in [0,1] (the width field); seen along ray
// with attenuation k (0: at the surface).
float pat_family_cover(PatParams P, vec3 p, float spacing, float stretch, float w, float density, float m, uint salt,
                       vec3 ray, float k) {
  if (w <= 0.0f || density <= 0.0f) return 0.0f;
  PatCells c = pat_voronoi(pat_stretch(p, P.veinNormal, stretch) * (1.0f / spacing), salt);
  if (pat_face_random(c) >= density) return 0.0f;
  // Swell and pinch: width from (1 - pinch) to (1 + pinch) times w as m goes 0 -> 1; at pinch
  // 1 the vein fades out where m is low.
  float width = w * max(1.0f - P.veinPinch + 2.0f * P.veinPinch * m, 0.0f);
  return pat_cells_cover(P, c, spacing, stretch, width, ray, k);
}

// Maps a turbulence sample (mean 0.5, mostly within 0.3-0.7) to [0,1].
float pat_spread(float t) { return min(max((t - 0.5f) * 3.0f + 0.5f, 0.0f), 1.0f); }

// The warped point at which the families are evaluated.
vec3 pat_vein_warped(PatParams P, vec3 objectPos, float t0, float t1, float t2) {
  return objectPos + (vec3(t0, t1, t2) - 0.5f) * (2.0f * P.veinWarp);
}

// ---- breccia (issue 16): fragments of many sizes ------------------------------------------
// A breccia is rock broken into angular fragments, cemented by a matrix of another mineral and
// often cut again by later calcite veins. Fragment sizes in broken rock follow a power law,
// N(> r) ~ r^-D with D about 2.5 (Turcotte, "Fractals and fragmentation", J. Geophys. Res. 91,
// 1986), which a fragmentation cascade produces (his renormalization model): each fragment of
// one scale is broken into the cells of the next finer family with probability p, the others
// stay whole. With spacings s_i and s_i+1 = s_i / r, D = 3 + ln p / ln r (Turcotte's is r = 2,
// D = ln(8p) / ln 2): p = 0.5 and r = 3 give D = 2.4. Here the cascade has three levels (the
// three families' spacings: clasts, smaller fragments, grit), so the law holds over the range
// the spacings span and not beyond; the finer cells are not nested in the coarser ones as
// Turcotte's cubes are, so a broken fragment's border cuts its pieces (more angular shards, the
// same counts to within the cells the border crosses).
//   * level 0: the dominant family's cells are the fragments, all its faces matrix;
//   * level 1: in a broken fragment every face of the secondary family is matrix (of the
//     secondary width) between smaller fragments; in a whole fragment its filled faces are cracks
//     inside the fragment (vein2Color, under the matrix: the fragment was veined before it broke);
//   * level 2: the same with the hairline family inside the broken level-1 fragments (grit);
//     elsewhere its filled faces are late calcite veins (vein3Color) drawn over fragments and
//     matrix alike.
// The matrix's width varies from face to face (0.4 to 1.6 times its width, at random per face:
// fragments that nearly touch beside fragments that float in the matrix) and along each face
// (the width field, as the veins). Each fragment, of whichever level, takes its own tint.

// A per-cell random in [0,1) for purpose `salt` (the cell's hash rehashed: independent bits).
float pat_cell_random(uint h, uint salt) { return pat_unit(pat_hash(h + salt)); }

// Width w modulated by the width field m in [0,1]: from (1 - pinch) to (1 + pinch) times w; at
// pinch 1 the vein fades out where m is low.
float pat_pinched(PatParams P, float w, float m) { return w * max(1.0f - P.veinPinch + 2.0f * P.veinPinch * m, 0.0f); }

// The matrix on the faces of cells c of full width w (before the per-face factor), at the surface.
float pat_matrix_cover(PatParams P, PatCells c, float spacing, float w) {
  return pat_vein_cover(c.edge * spacing, w * (0.4f + 1.2f * pat_face_random(c)), P.veinSoftness);
}

// The breccia's coverages at warped point p with width field m: (matrix, cracks inside whole
// fragments, late hairline veins, the random of the fragment p is in). The level-0 matrix is also
// seen along the ray (attenuation k), as the dominant veins are.
vec4 pat_breccia_covers(PatParams P, vec3 p, float m, vec3 ray, float k) {
  const uint kBroken = 0x2545f491u;
  PatCells f = pat_voronoi(pat_stretch(p, P.veinNormal, P.veinStretch) * (1.0f / P.veinSpacing.x), 0x9e3779b9u);
  float matrix = pat_cells_cover(P, f, P.veinSpacing.x, P.veinStretch,
                                 pat_pinched(P, P.veinWidth.x, m) * (0.4f + 1.2f * pat_face_random(f)), ray, k);
  uint fragment = f.h1;
  float s2 = sqrt(P.veinStretch);
  PatCells s = pat_voronoi(pat_stretch(p, P.veinNormal, s2) * (1.0f / P.veinSpacing.y), 0x165667b1u);
  float w1 = pat_pinched(P, P.veinWidth.y, m);
  bool broken = pat_cell_random(f.h1, kBroken) < P.fragmentSplit;
  float crack = 0.0f;
  if (broken) {
    matrix = max(matrix, pat_matrix_cover(P, s, P.veinSpacing.y, w1));
    fragment = s.h1;
  } else if (pat_face_random(s) < P.veinDensity.y) {
    crack = pat_vein_cover(s.edge * P.veinSpacing.y, w1, P.veinSoftness);
  }
  PatCells h = pat_voronoi(p * (1.0f / P.veinSpacing.z), 0x27d4eb2fu);
  float w2 = pat_pinched(P, P.veinWidth.z, 1.0f - m);
  float hair = 0.0f;
  if (broken && pat_cell_random(s.h1, kBroken) < P.fragmentSplit) {
    matrix = max(matrix, pat_matrix_cover(P, h, P.veinSpacing.z, w2));
    fragment = h.h1;
  } else if (pat_face_random(h) < P.veinDensity.z) {
    hair = pat_vein_cover(h.edge * P.veinSpacing.z, w2, P.veinSoftness);
  }
  return vec4(matrix, crack, hair, pat_cell_random(fragment, 0x85ebca6bu));
}

// The three families' coverages at warped point p with width field m: (dominant, secondary,
// hairline), w unused (0); breccia: pat_breccia_covers.
vec4 pat_vein_covers(PatParams P, vec3 p, float m, vec3 ray, float k) {
  if (P.veinModel == PAT_VEINS_BRECCIA) return pat_breccia_covers(P, p, m, ray, k);
  // Seen through the polish: the dominant family only (the finer veins' buried parts are as
  // thin as they are, well under a pixel at the sizes they are drawn at, and cost as much).
  float hair = pat_family_cover(P, p, P.veinSpacing.z, 1.0f, P.veinWidth.z, P.veinDensity.z, 1.0f - m, 0x27d4eb2fu, ray, 0.0f);
  float secondary =
      pat_family_cover(P, p, P.veinSpacing.y, sqrt(P.veinStretch), P.veinWidth.y, P.veinDensity.y, m, 0x165667b1u, ray, 0.0f);
  float dominant =
      pat_family_cover(P, p, P.veinSpacing.x, P.veinStretch, P.veinWidth.x, P.veinDensity.x, m, 0x9e3779b9u, ray, k);
  return vec4(dominant, secondary, hair, 0.0f);
}

// The vein model at object point p, given the four turbulence samples at
// pat_vein_sample_point(P, p, 0..3) (the caller evaluates them, or reads them from the grid):
// the colour in xyz, and in w the value before colour, as the paper's: 0 at the heart of a
// vein, 1 in the ground. Seen along the refracted view ray `ray` (object space, unit) with
// attenuation k per object unit (see "veins seen through the polish"); k = 0: at the surface.
vec4 pat_vein_shade_seen(PatParams P, vec3 objectPos, float t0, float t1, float t2, float t3, vec3 ray, float k) {
  vec4 cov = pat_vein_covers(P, pat_vein_warped(P, objectPos, t0, t1, t2), pat_spread(t3), ray, k);
  // Ground: clouds (the third warp sample, a broad turbulence); breccia fragments' tints.
  vec3 c = pat_mix3(P.baseColor, P.cloudColor, P.cloudAmount * pat_spread(t2));
  if (P.veinModel == PAT_VEINS_BRECCIA) {
    // Fragment tint; the cracks inside fragments under the matrix, the late veins over it.
    c = pat_mix3(c, P.cloudColor, P.fragmentTint * cov.w);
    c = pat_mix3(c, P.vein2Color, cov.y);
    c = pat_mix3(c, P.veinColor, cov.x);
    c = pat_mix3(c, P.vein3Color, cov.z);
  } else {
    c = pat_mix3(c, P.vein3Color, cov.z);
    c = pat_mix3(c, P.vein2Color, cov.y);
    c = pat_mix3(c, P.veinColor, cov.x);
  }
  // Grain: one octave of value noise at 1.5 texels, a multiplicative speckle.
  float g = pat_grain(pat_texel_pos(P, objectPos) * 0.6667f, 0x3c6ef372u);
  c = c * (1.0f + P.grainAmount * (g - 0.5f));
  return vec4(c.x, c.y, c.z, 1.0f - max(cov.x, max(cov.y, cov.z)));
}
vec4 pat_vein_shade(PatParams P, vec3 objectPos, float t0, float t1, float t2, float t3) {
  return pat_vein_shade_seen(P, objectPos, t0, t1, t2, t3, vec3(0.0f), 0.0f);
}
vec3 pat_vein_albedo(PatParams P, vec3 objectPos, float t0, float t1, float t2, float t3) {
  vec4 s = pat_vein_shade(P, objectPos, t0, t1, t2, t3);
  return vec3(s.x, s.y, s.z);
}
float pat_vein_value(PatParams P, vec3 objectPos, float t0, float t1, float t2, float t3) {
  return pat_vein_shade(P, objectPos, t0, t1, t2, t3).w;
}

// The turbulence samples evaluated (the reference; the GPU may read them from the grid).
float pat_vein_turbulence(PatParams P, vec3 objectPos, int k) {
  return pat_vein_turbulence3(P, pat_vein_sample_point(P, objectPos, k));
}
vec3 pat_vein_albedo_at(PatParams P, vec3 objectPos) {
  return pat_vein_albedo(P, objectPos, pat_vein_turbulence(P, objectPos, 0), pat_vein_turbulence(P, objectPos, 1),
                         pat_vein_turbulence(P, objectPos, 2), pat_vein_turbulence(P, objectPos, 3));
}
float pat_vein_value_at(PatParams P, vec3 objectPos) {
  return pat_vein_value(P, objectPos, pat_vein_turbulence(P, objectPos, 0), pat_vein_turbulence(P, objectPos, 1),
                        pat_vein_turbulence(P, objectPos, 2), pat_vein_turbulence(P, objectPos, 3));
}
