#include "marble/noise/marble_pattern.h"

#include "marble/noise/turbulence_grid.h"

#include <cmath>
#include <cstdint>
#include <vector>

// ONE SOURCE OF TRUTH. shaders/pattern_core.glsl is the body of the pattern; the GPU compiles
// it (through marble_pattern.glsl) and so does this file, right here, by #including the raw
// file inside a namespace that makes GLSL's vocabulary C++: GLM's vec2/vec3 and functions,
// `uint` as uint32_t, and float-only overloads of the scalar functions (so no call slips into
// double precision, and so floor is an exact, inlined one instead of a libm call). The .glsl is
// written in the subset both languages share (see its header). CMake also embeds the same
// file into the binary for the shader library, so there is no copy to drift.
namespace marble::patglsl {
using namespace glm;
using uint = uint32_t;

// Exact floor for |x| < 2^31 (texel coordinates are far smaller); identical to floorf there.
inline float floor(float x) {
  const float t = static_cast<float>(static_cast<int32_t>(x));
  return t > x ? t - 1.0f : t;
}
inline float sin(float x) { return std::sin(x); }
inline float abs(float x) { return std::fabs(x); }
inline float sqrt(float x) { return std::sqrt(x); }
inline float exp(float x) { return std::exp(x); }
inline float pow(float x, float y) { return std::pow(x, y); }
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline vec2 floor(vec2 v) { return vec2(floor(v.x), floor(v.y)); }
inline vec3 floor(vec3 v) { return vec3(floor(v.x), floor(v.y), floor(v.z)); }
inline vec3 abs(vec3 v) { return vec3(std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)); }

#include "../../../shaders/pattern_core.glsl"
}  // namespace marble::patglsl

namespace marble {
namespace {

using patglsl::PatParams;

PatParams toParams(const Material& m) {
  PatParams P;
  P.seed = m.seed;
  P.resolution = static_cast<float>(m.resolution);
  P.basis = m.basis == NoiseBasis::Perlin ? patglsl::PAT_BASIS_PERLIN : patglsl::PAT_BASIS_VALUE;
  P.mapping = m.mapping == PatternMapping::Planar      ? patglsl::PAT_MAP_PLANAR
              : m.mapping == PatternMapping::Triplanar ? patglsl::PAT_MAP_TRIPLANAR
                                                       : patglsl::PAT_MAP_SOLID;
  P.period = glm::vec3(m.x_period, m.y_period, m.z_period);
  P.turbPower = m.turb_power;
  P.turbSize = m.turb_size;
  P.scale = m.pattern_scale;
  P.sharpness = m.vein_sharpness;
  P.vein2Amount = m.vein2_amount;
  P.baseColor = m.base_color;
  P.veinColor = m.vein_color;
  P.vein2Color = m.vein2_color;
  const VeinUniformValues v = veinUniformValues(m);
  P.veinModel = v.model;
  P.veinSpacing = m.vein_spacing;
  P.veinWidth = m.vein_width;
  P.veinDensity = m.vein_density;
  P.veinNormal = v.direction;
  P.veinStretch = m.vein_stretch;
  P.veinWarp = m.vein_warp;
  P.veinPinch = m.vein_pinch;
  P.veinSoftness = m.vein_softness;
  P.vein3Color = m.vein3_color;
  P.cloudColor = m.cloud_color;
  P.cloudAmount = m.cloud_amount;
  P.grainAmount = m.grain_amount;
  P.fragmentTint = m.fragment_tint;
  P.fragmentSplit = m.fragment_split;
  return P;
}

}  // namespace

VeinUniformValues veinUniformValues(const Material& m) {
  const int model = m.vein_model == VeinModel::Network   ? patglsl::PAT_VEINS_NETWORK
                    : m.vein_model == VeinModel::Breccia ? patglsl::PAT_VEINS_BRECCIA
                                                         : patglsl::PAT_VEINS_PAPER;
  return {model, veinDirection(m)};
}

float veinPatternValue(const Material& m, glm::vec3 objectPos) { return patglsl::pat_vein_value_at(toParams(m), objectPos); }
glm::vec3 veinAlbedo(const Material& m, glm::vec3 objectPos) { return patglsl::pat_vein_albedo_at(toParams(m), objectPos); }
glm::vec4 veinShadeSeen(const Material& m, glm::vec3 objectPos, glm::vec3 ray, float k) {
  const PatParams P = toParams(m);
  return patglsl::pat_vein_shade_seen(P, objectPos, patglsl::pat_vein_turbulence(P, objectPos, 0),
                                      patglsl::pat_vein_turbulence(P, objectPos, 1), patglsl::pat_vein_turbulence(P, objectPos, 2),
                                      patglsl::pat_vein_turbulence(P, objectPos, 3), ray, k);
}

void veinAlbedoRow(const Material& m, glm::vec3 origin, glm::vec3 step, int count, glm::vec3* out, float* valueOut) {
  const PatParams P = toParams(m);
  auto point = [&](int i) { return origin + static_cast<float>(i) * step; };
  std::vector<float> t[4];
  const bool alongX = step.y == 0.0f && step.z == 0.0f;
  if (alongX) {
    // The four samples' texel points share y and z along the row: the turbulence by rows.
    std::vector<float> xs(static_cast<size_t>(count));
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < count; ++i) xs[static_cast<size_t>(i)] = patglsl::pat_vein_sample_point(P, point(i), k).x;
      const glm::vec3 q = patglsl::pat_vein_sample_point(P, point(0), k);
      t[k].resize(static_cast<size_t>(count));
      veinTurbulenceRow(m, xs.data(), q.y, q.z, count, t[k].data());
    }
  }
  for (int i = 0; i < count; ++i) {
    const glm::vec3 p = point(i);
    float s[4];
    for (int k = 0; k < 4; ++k)
      s[k] = alongX ? t[k][static_cast<size_t>(i)] : patglsl::pat_vein_turbulence(P, p, k);
    const glm::vec4 shade = patglsl::pat_vein_shade(P, p, s[0], s[1], s[2], s[3]);  // colour and value at once
    if (out) out[i] = glm::vec3(shade.x, shade.y, shade.z);
    if (valueOut) valueOut[i] = shade.w;
  }
}

float whiteNoise(const Material& m, glm::vec2 q) {
  return patglsl::pat_white2(patglsl::floor(q), static_cast<float>(m.resolution), patglsl::pat_hash(m.seed));
}
float whiteNoise3(const Material& m, glm::vec3 q) {
  return patglsl::pat_white3(patglsl::floor(q), static_cast<float>(m.resolution), patglsl::pat_hash(m.seed));
}
float smoothNoise(const Material& m, glm::vec2 p) {
  const PatParams P = toParams(m);
  return patglsl::pat_smooth2(p, P.resolution, patglsl::pat_hash(P.seed), P.basis);
}
float smoothNoise3(const Material& m, glm::vec3 p) {
  const PatParams P = toParams(m);
  return patglsl::pat_smooth3(p, P.resolution, patglsl::pat_hash(P.seed), P.basis);
}
float turbulence(const Material& m, glm::vec2 q) { return patglsl::pat_turbulence2(toParams(m), q); }
float turbulence3(const Material& m, glm::vec3 q) { return patglsl::pat_turbulence3(toParams(m), q); }
float sinePattern(const Material& m, glm::vec2 q) { return patglsl::pat_pattern2(toParams(m), q); }
float sinePattern3(const Material& m, glm::vec3 q) { return patglsl::pat_pattern3(toParams(m), q); }

float perlinNoise2(glm::vec2 p, float period, uint32_t seed) {
  return patglsl::pat_perlin2_signed(p, period, patglsl::pat_hash(seed));
}
float perlinNoise3(glm::vec3 p, float period, uint32_t seed) {
  return patglsl::pat_perlin3_signed(p, period, patglsl::pat_hash(seed));
}

glm::vec3 texelPosition(const Material& m, glm::vec3 objectPos) { return patglsl::pat_texel_pos(toParams(m), objectPos); }
float mirrorTexel(float s, float W) { return patglsl::pat_mirror(s, W); }
float marblePatternValue(const Material& m, glm::vec3 objectPos, glm::vec3 objectNormal) {
  if (m.vein_model != VeinModel::Paper) return veinPatternValue(m, objectPos);
  return patglsl::pat_value_at(toParams(m), objectPos, objectNormal);
}
glm::vec3 patternColor(const Material& m, float v) { return patglsl::pat_color(toParams(m), v); }
glm::vec3 marbleAlbedo(const Material& m, glm::vec3 objectPos, glm::vec3 objectNormal) {
  if (m.vein_model != VeinModel::Paper) return veinAlbedo(m, objectPos);
  return patglsl::pat_albedo(toParams(m), objectPos, objectNormal);
}

AlbedoSampler::AlbedoSampler(const Material& m, double expectedPoints)
    : material_(m), resolution_(turbulenceGridSize(m)), channels_(turbulenceGridChannels(m)) {
  if (turbulenceGridDimensions(m) != 3) return;
  const double gridTexels = std::pow(static_cast<double>(resolution_), 3.0) * channels_;
  const double perPoint = m.vein_model != VeinModel::Paper ? 4.0 : 1.0;  // turbulences at one point
  if (expectedPoints * perPoint < 0.25 * gridTexels) return;
  grid_ = bakeTurbulenceGrid(m);
}

float AlbedoSampler::gridTurbulence(glm::vec3 g, int channel) const {
  // The texture unit's GL_LINEAR with GL_REPEAT at grid coordinate g (texel i at g = i;
  // marble_pattern.glsl samples at (g + 0.5) / size). The vein models' grid: g = q / 2.
  const int w = resolution_;
  const glm::vec3 f0 = glm::vec3(patglsl::floor(g.x), patglsl::floor(g.y), patglsl::floor(g.z));
  const glm::vec3 f = g - f0;
  auto wrap = [w](float i) {
    const int k = static_cast<int>(i) % w;
    return k < 0 ? k + w : k;
  };
  const int x0 = wrap(f0.x), y0 = wrap(f0.y), z0 = wrap(f0.z);
  const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == w ? 0 : y0 + 1, z1 = z0 + 1 == w ? 0 : z0 + 1;
  const auto c = static_cast<size_t>(channels_);
  auto at = [&](int x, int y, int z) {
    return static_cast<float>(grid_[((static_cast<size_t>(z) * w + y) * w + x) * c + static_cast<size_t>(channel)]);
  };
  auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
  const float c00 = lerp(at(x0, y0, z0), at(x1, y0, z0), f.x), c10 = lerp(at(x0, y1, z0), at(x1, y1, z0), f.x);
  const float c01 = lerp(at(x0, y0, z1), at(x1, y0, z1), f.x), c11 = lerp(at(x0, y1, z1), at(x1, y1, z1), f.x);
  return lerp(lerp(c00, c10, f.y), lerp(c01, c11, f.y), f.z) * (1.0f / 65535.0f);
}

glm::vec3 AlbedoSampler::operator()(glm::vec3 objectPos, glm::vec3 objectNormal) const {
  if (grid_.empty()) return marbleAlbedo(material_, objectPos, objectNormal);
  const PatParams P = toParams(material_);
  if (material_.vein_model != VeinModel::Paper) {
    // The four samples at one texel of the vein grid (turbulence_grid.h).
    const glm::vec3 g = patglsl::pat_texel_pos(P, objectPos) * 0.5f;
    float t[4];
    for (int k = 0; k < 4; ++k) t[k] = gridTurbulence(g, k);
    return patglsl::pat_vein_albedo(P, objectPos, t[0], t[1], t[2], t[3]);
  }
  // The solid mapping (the only paper-model mapping with a 3D grid): pat_value_at's first case.
  const glm::vec3 q = patglsl::pat_texel_pos(P, objectPos);
  return patglsl::pat_color(P, patglsl::pat_sine(patglsl::pat_ramp3(P, q), gridTurbulence(q, 0), P.turbPower));
}

// ---- batched rows ----
// Each octave of value noise is, along a row, a piecewise-linear function of x whose knots are
// the lattice columns (pat_value2_column / pat_value3_column: the y/z interpolation done
// first). We compute each column once and walk the row; every float operation is the one the
// per-point reference performs, in the same order, so the results are bit-identical (tested).
namespace {

template <typename ColumnFn>
void accumulateOctave(const float* xs, int count, float size, float inv, float period, float* acc, ColumnFn column) {
  using patglsl::pat_lerp;
  using patglsl::pat_wrap;
  float cell = 0.0f, c0 = 0.0f, c1 = 0.0f, w0 = 0.0f, w1 = 0.0f;
  bool have = false;
  for (int i = 0; i < count; ++i) {
    const float px = xs[i] * inv;
    const float ix = patglsl::floor(px);
    const float fx = px - ix;
    if (!have || ix != cell) {
      if (have && ix == cell + 1.0f) {
        c0 = c1;
        w0 = w1;
      } else {
        w0 = pat_wrap(ix, period);
        c0 = column(w0);
      }
      w1 = patglsl::pat_next(w0, period);
      c1 = column(w1);
      cell = ix;
      have = true;
    }
    acc[i] += pat_lerp(c0, c1, fx) * size;
  }
}

void finishRow(const PatParams& P, const float* xs, float yz, int count, float* sum, float* turbOut,
               float* valueOut) {
  for (int i = 0; i < count; ++i) {
    const float t = sum[i] / (2.0f * P.turbSize);
    if (turbOut) turbOut[i] = t;
    if (valueOut) {
      // The same expression as pat_pattern2/3: (x*px + y*py [+ z*pz]) / W, left to right.
      const float ramp = (xs[i] * P.period.x + yz) / P.resolution;
      valueOut[i] = patglsl::pat_sine(ramp, t, P.turbPower);
    }
  }
}

}  // namespace

void patternRow2(const Material& m, const float* xs, float y, int count, float* turbOut, float* valueOut) {
  const PatParams P = toParams(m);
  if (P.basis != patglsl::PAT_BASIS_VALUE) {
    for (int i = 0; i < count; ++i) {
      const glm::vec2 q(xs[i], y);
      const float t = patglsl::pat_turbulence2(P, q);
      if (turbOut) turbOut[i] = t;
      if (valueOut) valueOut[i] = patglsl::pat_sine((q.x * P.period.x + q.y * P.period.y) / P.resolution, t, P.turbPower);
    }
    return;
  }
  const uint32_t sh = patglsl::pat_hash(P.seed);
  std::vector<float> sum(static_cast<size_t>(count), 0.0f);
  for (float size = P.turbSize, inv = 1.0f / P.turbSize; size >= 1.0f; size *= 0.5f, inv *= 2.0f) {
    const float period = patglsl::pat_octave_period(P.resolution, inv);
    const float py = y * inv;
    const float iy = patglsl::floor(py);
    const float fy = py - iy;
    const uint32_t h0 = patglsl::pat_hash_y(patglsl::pat_wrap(iy, period), sh);
    const uint32_t h1 = patglsl::pat_hash_y(patglsl::pat_next(patglsl::pat_wrap(iy, period), period), sh);
    accumulateOctave(xs, count, size, inv, period, sum.data(),
                     [&](float x) { return patglsl::pat_value2_column(x, h0, h1, fy); });
  }
  finishRow(P, xs, y * P.period.y, count, sum.data(), turbOut, valueOut);
}

namespace {

// The octaves of size >= minSize of the turbulence's sum at (xs[i], y, z) added to sum[i] (value
// basis); returns the sum of their weights (pat_turbulence3 / pat_vein_turbulence3's loops).
float accumulateTurbulence3(const PatParams& P, const float* xs, float y, float z, int count, float minSize, float* sum) {
  const uint32_t sh = patglsl::pat_hash(P.seed);
  float weight = 0.0f;
  for (float size = P.turbSize, inv = 1.0f / P.turbSize; size >= minSize; size *= 0.5f, inv *= 2.0f) {
    const float period = patglsl::pat_octave_period(P.resolution, inv);
    const float py = y * inv, pz = z * inv;
    const float iy = patglsl::floor(py), iz = patglsl::floor(pz);
    const float fy = py - iy, fz = pz - iz;
    const float y0 = patglsl::pat_wrap(iy, period), y1 = patglsl::pat_next(y0, period);
    const float z0 = patglsl::pat_wrap(iz, period), z1 = patglsl::pat_next(z0, period);
    const uint32_t h00 = patglsl::pat_hash_yz(y0, z0, sh), h10 = patglsl::pat_hash_yz(y1, z0, sh);
    const uint32_t h01 = patglsl::pat_hash_yz(y0, z1, sh), h11 = patglsl::pat_hash_yz(y1, z1, sh);
    accumulateOctave(xs, count, size, inv, period, sum,
                     [&](float x) { return patglsl::pat_value3_column(x, h00, h10, h01, h11, fy, fz); });
    weight += size;
  }
  return weight;
}

}  // namespace

void veinTurbulenceRow(const Material& m, const float* xs, float y, float z, int count, float* out) {
  const PatParams P = toParams(m);
  if (P.basis != patglsl::PAT_BASIS_VALUE) {
    for (int i = 0; i < count; ++i) out[i] = patglsl::pat_vein_turbulence3(P, glm::vec3(xs[i], y, z));
    return;
  }
  std::vector<float> sum(static_cast<size_t>(count), 0.0f);
  const float weight = accumulateTurbulence3(P, xs, y, z, count, patglsl::pat_vein_min_octave(P), sum.data());
  for (int i = 0; i < count; ++i) out[i] = sum[static_cast<size_t>(i)] / weight;
}

glm::vec3 veinSampleOffset(const Material& m, int k) { return patglsl::pat_vein_sample_offset(toParams(m), k); }

void patternRow3(const Material& m, const float* xs, float y, float z, int count, float* turbOut, float* valueOut) {
  const PatParams P = toParams(m);
  if (P.basis != patglsl::PAT_BASIS_VALUE) {
    for (int i = 0; i < count; ++i) {
      const glm::vec3 q(xs[i], y, z);
      const float t = patglsl::pat_turbulence3(P, q);
      if (turbOut) turbOut[i] = t;
      if (valueOut)
        valueOut[i] = patglsl::pat_sine((q.x * P.period.x + q.y * P.period.y + q.z * P.period.z) / P.resolution, t,
                                        P.turbPower);
    }
    return;
  }
  std::vector<float> sum(static_cast<size_t>(count), 0.0f);
  accumulateTurbulence3(P, xs, y, z, count, 1.0f, sum.data());
  // pat_pattern3's ramp is ((x*px + y*py) + z*pz) / W: pass the (x*px + y*py) part per point.
  for (int i = 0; i < count; ++i) {
    const float t = sum[i] / (2.0f * P.turbSize);
    if (turbOut) turbOut[i] = t;
    if (valueOut)
      valueOut[i] = patglsl::pat_sine((xs[i] * P.period.x + y * P.period.y + z * P.period.z) / P.resolution, t,
                                      P.turbPower);
  }
}

}  // namespace marble
