#pragma once
// Fresnel's exact reflectance of a dielectric of relative index eta for unpolarized light at
// cosine c (Walter et al. 2007, eq. 22): what shaders/marble_shading.glsl's fresnel_dielectric
// computes, for the tests' expected values.
#include <cmath>

namespace marble::test {

inline double fresnelDielectric(double c, double eta) {
  const double g = std::sqrt(eta * eta - 1.0 + c * c);
  const double a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

}  // namespace marble::test
