#pragma once
// The marble pattern's turbulence as a texture (noise/turbulence_grid.h explains why one
// filtered fetch of it equals the six octaves the pattern would otherwise evaluate per pixel):
// baked when the material's turbulence changes (seed, resolution, turb_size, basis, mapping),
// kept while only what is applied after it (turb_power, periods, colours, scale) changes.
#include <cstddef>

#include "marble/gl/handles.h"
#include "marble/noise/turbulence_grid.h"
#include "marble/render/shader_constants.h"

namespace marble {

// Texture unit of the grid in every program that evaluates the pattern (marble_pattern.glsl).
inline constexpr GLuint kTurbulenceGridUnit = shader::UNIT_TURBULENCE_GRID;

class TurbulenceTexture {
public:
  // The grid of m's turbulence, baked now if it is not the one held (a 256^3 grid: about
  // 0.2 s on two cores), or 0 when m's turbulence has no exact grid (or grids are disabled):
  // the pattern is then evaluated per pixel.
  GLuint update(const Material& m);
  // Off: every pass evaluates the pattern per pixel (to compare the two; the pictures agree
  // within rounding, tests/turbulence_grid_gl_test.cpp).
  void setEnabled(bool enabled) { enabled_ = enabled; }
  size_t bytes() const { return bytes_; }

private:
  bool enabled_ = true;
  TurbulenceGridKey key_;
  gl::Texture texture_;
  size_t bytes_ = 0;
};

}  // namespace marble
