// Cycles' subsurface radius -> volume coefficients (material_scattering.h). The formulas are
// Cycles 3.4.1's, re-derived from their papers where they have one; keep them in step with
// tools/cycles_reference.py, which hands Cycles the radius itself.
#include "marble/scene/material_scattering.h"

#include <algorithm>
#include <cmath>

namespace marble {
namespace {

// 4/3 A of the dipole's boundary condition (Jensen et al. 2001, eq. 2 and the F_dr fit after it,
// as Cycles writes it: F_dr = -1.440/n^2 + 0.710/n + 0.668 + 0.0636 n).
double fourThirdsA(double ior) {
  const double inv = 1.0 / ior;
  const double fdr = inv * (-1.440 * inv + 0.710) + 0.668 + 0.0636 * ior;
  return 4.0 / 3.0 * (1.0 + fdr) / (1.0 - fdr);
}

double reflectance(double alphaPrime, double fourThirdsA_) {
  const double s = std::sqrt(3.0 * (1.0 - alphaPrime));
  return 0.5 * alphaPrime * (1.0 + std::exp(-fourThirdsA_ * s)) * std::exp(-s);
}

double clampedIor(float ior) { return std::clamp(static_cast<double>(ior), 1.01, 3.8); }

}  // namespace

float dipoleReflectance(float alphaPrime, float ior) {
  return static_cast<float>(reflectance(alphaPrime, fourThirdsA(clampedIor(ior))));
}

float cyclesAlphaPrime(float albedo, float ior) {
  if (albedo < 1e-4f) return 0.0f;
  if (albedo >= 0.995f) return 0.999999f;
  const double a = fourThirdsA(clampedIor(ior));
  double lo = 0.0, hi = 1.0, mid = 0.5;
  for (int i = 0; i < 12; ++i) {  // Cycles' count: its answer, not a closer one
    mid = 0.5 * (lo + hi);
    if (reflectance(mid, a) < albedo) lo = mid;
    else hi = mid;
  }
  return static_cast<float>(mid);
}

float cyclesSingleScatteringAlbedo(float albedo) {
  // Wrenninge et al.'s coefficients at g = 0 (each polynomial's constant term; B and E add their
  // exponential's value at 0).
  const double A = 1.8260523782, B = 4.98511194385 + 0.127355959438, C = 1.09686102424;
  const double D = 0.496310210422, E = 4.23190299701 + 0.00310603949088, F = 2.40602999408;
  const double x = std::max(static_cast<double>(albedo), 0.0);
  const double blend = std::pow(x, 0.25);
  const double alpha =
      (1.0 - blend) * A * std::pow(std::atan(B * x), C) + blend * D * std::pow(std::atan(E * x), F);
  return static_cast<float>(std::clamp(alpha, 0.2, 0.999999));
}

ScatteringCoefficients coefficientsFromRadius(glm::vec3 albedo, glm::vec3 radiusMm, float ior) {
  ScatteringCoefficients c{};
  for (int i = 0; i < 3; ++i) {
    const double alphaPrime = cyclesAlphaPrime(albedo[i], ior);
    const double radius = std::max(static_cast<double>(radiusMm[i]), 1e-6) * std::sqrt(3.0 * (1.0 - alphaPrime));
    const double sigmaT = 1.0 / std::max(radius, 1e-16);
    const double alpha = cyclesSingleScatteringAlbedo(albedo[i]);
    c.sigma_s_mm[i] = static_cast<float>(alpha * sigmaT);
    c.sigma_a_mm[i] = static_cast<float>((1.0 - alpha) * sigmaT);
  }
  return c;
}

void resolveScattering(Material& m) {
  if (m.scattering != ScatteringForm::Radius) return;
  const ScatteringCoefficients c = coefficientsFromRadius(m.base_color, m.subsurface_radius_mm, m.ior);
  m.sigma_a_mm = c.sigma_a_mm;
  m.sigma_s_mm = c.sigma_s_mm;
}

float diffusionAttenuationMm(const Material& m) {
  const glm::vec3 a = m.sigma_a_mm, t = m.sigma_a_mm + m.sigma_s_mm;
  const glm::vec3 tr = glm::sqrt(3.0f * glm::max(a, glm::vec3(0.0f)) * glm::max(t, glm::vec3(0.0f)));
  return (tr.x + tr.y + tr.z) / 3.0f;
}

}  // namespace marble
