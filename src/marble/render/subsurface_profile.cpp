#include "marble/render/subsurface_profile.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace marble {

namespace {
// The walk's fit (tools/walk_profile.cpp, 200,000 walks per row): d / l at u = -log10(1 - alpha).
// Below u = 2 (alpha < 0.99) Christensen & Burley's own searchlight fit s = 1.85 - A + 7|A - 0.8|^3
// (A: the walk's total reflectance) is within 12 % of these; at marble's u = 2.1-2.6, within 5 %.
constexpr float kRowU[] = {0.5f, 1.0f, 1.5f, 2.0f, 2.25f, 2.5f, 2.75f, 3.0f, 3.5f, 4.0f, 5.0f, 6.0f};
constexpr float kRowDOverL[] = {0.375f, 0.546f, 0.724f, 0.888f, 0.952f, 1.007f,
                                1.038f, 1.056f, 1.078f, 1.091f, 1.089f, 1.084f};
constexpr int kRows = static_cast<int>(sizeof(kRowU) / sizeof(kRowU[0]));

// The 1D marginal of Burley's profile with d = 1 (up to a constant factor, which the blur's
// normalization takes out): K0(x) + K0(x / 3).
double marginal(double x) { return std::cyl_bessel_k(0.0, x) + std::cyl_bessel_k(0.0, x / 3.0); }

// Integral of the marginal over [a, b] (in units of d), midpoint rule: finite at x = 0, where
// K0 has its (integrable) logarithmic peak.
double marginalIntegral(double a, double b) {
  constexpr int kSteps = 48;
  const double h = (b - a) / kSteps;
  double sum = 0.0;
  for (int k = 0; k < kSteps; ++k) sum += marginal(a + (k + 0.5) * h);
  return sum * h;
}
}  // namespace

float burleyDOverMeanFreePath(float alpha) {
  const float u = -std::log10(std::max(1.0f - alpha, 1e-7f));
  if (u <= kRowU[0]) return kRowDOverL[0];
  for (int i = 1; i < kRows; ++i) {
    if (u <= kRowU[i]) {
      const float t = (u - kRowU[i - 1]) / (kRowU[i] - kRowU[i - 1]);
      return kRowDOverL[i - 1] + t * (kRowDOverL[i] - kRowDOverL[i - 1]);
    }
  }
  return kRowDOverL[kRows - 1];
}

glm::vec3 burleyShapeD(const Material& m) {
  const glm::vec3 sigmaT = glm::max(m.sigma_a_mm + m.sigma_s_mm, glm::vec3(1e-4f));
  glm::vec3 d;
  for (int c = 0; c < 3; ++c) d[c] = burleyDOverMeanFreePath(m.sigma_s_mm[c] / sigmaT[c]) / sigmaT[c];
  return d;
}

float subsurfaceReachMm(const Material& m) {
  const glm::vec3 d = burleyShapeD(m);
  return kReachInD * std::max(d.r, std::max(d.g, d.b));
}

SubsurfaceKernel subsurfaceKernel(const glm::vec3& d, float reachMm, int taps) {
  SubsurfaceKernel k;
  k.taps = std::clamp(taps, 1, static_cast<int>(shader::MAX_TAPS));
  for (int i = 0; i <= k.taps; ++i) {
    const float f = static_cast<float>(i) / static_cast<float>(k.taps);
    k.offsetsMm[i] = reachMm * f * f;
  }
  for (int i = 0; i <= k.taps; ++i) {
    // Tap i stands for the part of the axis nearer to it than to its neighbours (tap 0: both
    // sides of the centre, counted once; the last: out to the reach).
    const double a = i == 0 ? 0.0 : 0.5 * (k.offsetsMm[i - 1] + k.offsetsMm[i]);
    const double b = i == k.taps ? k.offsetsMm[i] : 0.5 * (k.offsetsMm[i] + k.offsetsMm[i + 1]);
    for (int c = 0; c < 3; ++c) {
      const double dc = std::max(static_cast<double>(d[c]), 1e-6);
      k.weights[i][c] = static_cast<float>((i == 0 ? 2.0 : 1.0) * dc * marginalIntegral(a / dc, b / dc));
    }
  }
  return k;
}

}  // namespace marble
