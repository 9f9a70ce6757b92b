#pragma once
// The marble pattern's turbulence as a texture (noise/turbulence_grid.h explains why one
// filtered fetch of it equals the six octaves the pattern would otherwise evaluate per pixel):
// baked when the material's turbulence changes (seed, resolution, turb_size, basis, mapping),
// kept while only what is applied after it (turb_power, periods, colours, scale) changes.
#include <cstddef>

#include "marble/gl/handles.h"
#include "marble/noise/turbulence_grid.h"

namespace marble {

// Texture unit of the grid in every program that evaluates the pattern (marble_pattern.glsl).
inline constexpr GLuint kTurbulenceGridUnit = 8;

class TurbulenceTexture {
public:
  // The grid of m's turbulence, or 0: the pattern is then evaluated per pixel. 0 when m's
  // turbulence has no exact grid (or grids are disabled), and the first time a turbulence is
  // asked for: a single frame (`marble render`) or a seed being clicked through would pay the
  // bake (256^3: ~0.36 s on two cores) for one use. The second request for the same turbulence
  // bakes it; later ones return it.
  GLuint update(const Material& m);
  // Off: every pass evaluates the pattern per pixel (to compare the two; the pictures agree
  // within rounding, tests/turbulence_grid_gl_test.cpp).
  void setEnabled(bool enabled) { enabled_ = enabled; }
  size_t bytes() const { return bytes_; }

private:
  bool enabled_ = true;
  TurbulenceGridKey key_;          // what texture_ holds
  TurbulenceGridKey requestedKey_;  // the turbulence last asked for
  bool requested_ = false;
  gl::Texture texture_;
  size_t bytes_ = 0;
};

}  // namespace marble
