#pragma once
// The turbulence baked at integer texels, so the GPU can read it with one filtered texture
// fetch instead of evaluating six octaves of noise per pixel (issue 8: "the pattern baked or
// evaluated, whichever the numbers favour").
//
// Why one fetch is exact, not an approximation: with the value basis every octave is the
// multilinear (Lode's bilinear / trilinear) interpolation of its lattice. When every octave's
// cell size is an integer number of texels (turb_size a power of two), each texel cell
// [i, i+1]^n lies inside one cell of every octave, so on it every octave -- hence their
// weighted sum, the turbulence -- is a multilinear function. A multilinear function on a box
// is the multilinear interpolation of its values at the box's corners, which is exactly what
// the texture unit's linear filter computes from the grid baked here. The lattices wrap with
// period W = resolution texels when the octave sizes divide W, so a W^n grid with GL_REPEAT
// covers all of space. Differences from the per-point reference are rounding: float
// arithmetic (~1e-7) and the 16-bit storage (half a step, 7.6e-6).
#include <cstdint>
#include <vector>

#include "marble/scene/material.h"

namespace marble {

// Largest resolution baked for the solid mapping: 256^3 texels of 16 bits = 32 MiB. Beyond it
// the pattern is evaluated per pixel (512^3 would be 256 MiB).
inline constexpr int kMaxSolidTurbulenceGrid = 256;

// The vein models' grid (issue 16) is different: their turbulence stops at the 2-texel octave
// (pattern_core.glsl pat_vein_turbulence3), so it is multilinear on 2-texel cells and a grid of
// (W/2)^3 texels at the even texel points is exact by the same argument; each texel holds the
// four samples the model reads (at q + pat_vein_sample_offset(k), offsets even), so one fetch
// gives all four. Largest: 128^3 texels of 4 x 16 bits = 16 MiB.
inline constexpr int kMaxVeinTurbulenceGrid = 128;

// 3 (solid mapping, and the vein models whatever the mapping), 2 (planar, triplanar), or 0
// when the grid would not be exact (Perlin's basis: its fade curve is not multilinear;
// turb_size not a power of two dividing the resolution; for the vein models turb_size below 2)
// or too large (above kMaxSolidTurbulenceGrid, kMaxVeinTurbulenceGrid).
int turbulenceGridDimensions(const Material& m);

// What a grid depends on: materials with equal keys share one grid.
struct TurbulenceGridKey {
  uint32_t seed = 0;
  int resolution = 0;
  float turbSize = 0.0f;
  int dimensions = 0;
  bool veins = false;  // the vein models' four-sample grid
  bool operator==(const TurbulenceGridKey&) const = default;
};
TurbulenceGridKey turbulenceGridKey(const Material& m);

// Texels per axis and values per texel of m's grid: W and 1 for the paper's model, W/2 and 4
// for the vein models.
int turbulenceGridSize(const Material& m);
int turbulenceGridChannels(const Material& m);

// The paper's model: the turbulence at every integer texel (x fastest, then y, then z),
// W^dimensions values as unsigned normalized 16-bit (turbulence is in [0,1)). The vein models:
// at texel i = (x, y, z) of the (W/2)^3 grid, the four samples pat_vein_turbulence3(2i +
// offset(k)), k = 0..3, interleaved. Computed with the reference's row evaluation
// (patternRow2/3, veinTurbulenceRow: the same pattern_core.glsl the GPU runs) on all cores.
// Requires turbulenceGridDimensions(m) > 0.
std::vector<uint16_t> bakeTurbulenceGrid(const Material& m);

}  // namespace marble
