#pragma once
// The marble pattern on the CPU (paper §3.1): the reference the GPU is tested against, and what
// `marble texture` bakes. The arithmetic is not written here: marble_pattern.cpp compiles
// shaders/pattern_core.glsl as C++ (see the comment there), so CPU and GPU share one body.
//
// Units: "texel" coordinates q address the paper's W x W texture (W = Material::resolution);
// object-space positions p map to texels by q = p * (W / 2) / pattern_scale.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "marble/scene/material.h"

namespace marble {

// ---- stages (2D: the paper's texture, q in texels) ----
// White noise of the lattice cell containing q: [0,1), wraps with period W.
float whiteNoise(const Material& m, glm::vec2 q);
// Smooth noise (the material's basis) at lattice coordinates p (one unit = one cell), lattice
// period W cells: [0,1].
float smoothNoise(const Material& m, glm::vec2 p);
// Turbulence (octaves turb_size, turb_size/2, ... >= 1, weighted by size): [0,1).
float turbulence(const Material& m, glm::vec2 q);
// |sin(pi * (x*x_period/W + y*y_period/W + turb_power * turbulence))|: [0,1].
float sinePattern(const Material& m, glm::vec2 q);

// ---- 3D (solid marble, q in texels) ----
float whiteNoise3(const Material& m, glm::vec3 q);
float smoothNoise3(const Material& m, glm::vec3 p);
float turbulence3(const Material& m, glm::vec3 q);
float sinePattern3(const Material& m, glm::vec3 q);

// Perlin's improved noise, signed ([-1,1]), lattice coordinates, wrapping with `period` cells.
float perlinNoise2(glm::vec2 p, float period, uint32_t seed);
float perlinNoise3(glm::vec3 p, float period, uint32_t seed);

// ---- mappings and colour (what the GPU's marble_albedo computes) ----
glm::vec3 texelPosition(const Material& m, glm::vec3 objectPos);
// GL_MIRRORED_REPEAT on texel coordinates: [0,W] as is, mirrored beyond; result in [0,W].
float mirrorTexel(float s, float W);
// Pattern value in [0,1] for the material's mapping (normal used by triplanar only).
float marblePatternValue(const Material& m, glm::vec3 objectPos, glm::vec3 objectNormal);
// The colour ramp: v in [0,1] -> linear RGB.
glm::vec3 patternColor(const Material& m, float v);
glm::vec3 marbleAlbedo(const Material& m, glm::vec3 objectPos, glm::vec3 objectNormal);

// ---- the vein model (issue 16; pattern_core.glsl "vein networks") ----
// What the uniforms carry beyond the Material's own numbers: the model's PAT_VEINS_* value
// and the normalized vein direction (one place for both, used by the CPU and the GPU side).
struct VeinUniformValues {
  int model;
  glm::vec3 direction;
};
VeinUniformValues veinUniformValues(const Material& m);
// The vein model's value before colour (0 in a vein's heart, 1 in the ground) and colour at
// an object-space point; marblePatternValue / marbleAlbedo dispatch to these when
// m.vein_model != VeinModel::Paper.
float veinPatternValue(const Material& m, glm::vec3 objectPos);
glm::vec3 veinAlbedo(const Material& m, glm::vec3 objectPos);
// The vein model seen through the polish (pattern_core.glsl "veins seen through the polish"):
// colour (xyz) and value (w) at objectPos along the refracted view ray `ray` (object space,
// unit, into the stone) with attenuation k per object unit (0: the surface, = veinAlbedo).
glm::vec4 veinShadeSeen(const Material& m, glm::vec3 objectPos, glm::vec3 ray, float k);
// A row of object-space points origin + i * step, i < count, the colour and value of each (the
// fast path of `marble texture`: along x the four turbulence samples by rows; then the model
// per point with each Voronoi block and grain column computed once per row, marble_pattern.cpp
// "row memo"; on AVX2 CPUs 8 points at a time, vein_lanes.inc). Bit-identical to veinAlbedo /
// veinPatternValue at the same points (tested).
void veinAlbedoRow(const Material& m, glm::vec3 origin, glm::vec3 step, int count, glm::vec3* out, float* valueOut);
// Whether this CPU shades the vein rows 8 points at a time (AVX2), and how this thread's rows
// (veinAlbedoRow, AlbedoSampler::veinRow) have shaded their points so far: batches of 8 by the
// lanes, batches recomputed one point at a time because their lanes branched differently, and
// points shaded one at a time (rows' last points; every point without AVX2). For tests and
// benchmarks: the equality tests mean something for the lanes only where they ran.
struct VeinRowCounts {
  long long laneBatches = 0;
  long long divergedBatches = 0;
  long long singlePoints = 0;
};
bool veinRowsUseLanes();
// Whether the lanes shade on their AVX-512 build (where the CPU has AVX-512 F/VL/BW/DQ; the same
// bits as the AVX2 build, fewer spills), and a switch to the AVX2 build on such a CPU, so that the
// tests check both (process-wide; on by default).
bool veinRowsUseWideLanes();
void setVeinRowsWideLanes(bool on);
VeinRowCounts veinRowCounts();

// The vein model's turbulence (its octaves down to 2 texels, pattern_core.glsl
// pat_vein_turbulence3) at the texel points (xs[i], y, z), by rows as patternRow3; bit-identical
// to the per-point function.
void veinTurbulenceRow(const Material& m, const float* xs, float y, float z, int count, float* out);
// The texel offset of the vein model's turbulence sample k in 0..3 (pat_vein_sample_offset).
glm::vec3 veinSampleOffset(const Material& m, int k);

// ---- batched rows (the fast path: bit-identical to the functions above) ----
// A row of points (xs[i], y) or (xs[i], y, z) in texels. Lattice columns and the row's y/z
// hashes are computed once per cell instead of once per point (value basis; the Perlin basis
// falls back to per-point evaluation). xs in increasing order is fastest; any order is correct.
// turbOut and/or valueOut may be null.
void patternRow2(const Material& m, const float* xs, float y, int count, float* turbOut, float* valueOut);
void patternRow3(const Material& m, const float* xs, float y, float z, int count, float* turbOut, float* valueOut);

// ---- many points at once (`marble bake`) ----
// marbleAlbedo at arbitrary points, with the turbulence read from the baked grid
// (turbulence_grid.h) by trilinear interpolation, as the GPU reads it, where that grid is exact
// and solid (the value basis, turb_size a power of two dividing resolution <= 256; the solid
// mapping or a vein model), and worth its bake: when the points would evaluate at least a
// quarter as many turbulences as the grid has texels (one grid texel by rows costs about a
// fifth of one turbulence at a point: docs/performance.md, "Bake"). Otherwise, and for the
// planar and triplanar mappings of the paper's model, it is marbleAlbedo itself. The two agree
// to the grid's 16-bit rounding of the turbulence (tested); the sampler is read-only after
// construction, so threads share it.
class AlbedoSampler {
 public:
  AlbedoSampler(const Material& m, double expectedPoints);
  glm::vec3 operator()(glm::vec3 objectPos, glm::vec3 objectNormal) const;
  // The vein models' batched rows (as veinAlbedoRow: the points origin + i * step, i < count,
  // colour and value before colour) with the turbulence from this sampler's grid: equal to
  // operator() at each point bit for bit (tested). Rows along x read each grid column once;
  // without a grid it is veinAlbedoRow. Throws std::logic_error for the paper's model.
  void veinRow(glm::vec3 origin, glm::vec3 step, int count, glm::vec3* out, float* valueOut) const;
  bool usesGrid() const { return !grid_.empty(); }

 private:
  struct GridAxes {  // the 2 x 2 x 2 grid texels around a point and its weights
    int x0, x1, y0, y1, z0, z1;
    glm::vec3 f;
  };
  GridAxes gridAxes(glm::vec3 g) const;  // g in grid texels (vein models: q / 2)
  float gridColumn(const GridAxes& a, int x, int channel) const;  // raw 16-bit units
  // gridColumn of the four channels at the n columns from `first` (wrapped), channel k's at
  // table[k * stride + j]; the grid has four channels (the vein models').
  void gridColumns(const GridAxes& a, int32_t first, size_t n, size_t stride, float* table) const;
  float gridTurbulence(glm::vec3 g, int channel) const;
  Material material_;
  std::vector<uint16_t> grid_;  // W^3, x fastest; empty: evaluated per point
  int resolution_ = 0;  // the grid's texels per axis
  int channels_ = 1;
};

}  // namespace marble
