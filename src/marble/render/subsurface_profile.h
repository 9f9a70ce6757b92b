#pragma once
// The diffusion profile the `marble` mode's screen-space blur spreads entering light with
// (shaders/subsurface_blur.frag.glsl): its width per channel, its reach, and the separable taps'
// offsets and weights. Pure CPU; the blur pass uploads what this computes.
//
// Shape: Burley's normalized diffusion R(r) = (e^(-r/d) + e^(-r/(3d))) / (8 pi d r) (Christensen &
// Burley 2015), with d fitted to the random walk Cycles' RANDOM_WALK runs in the same stone
// (tools/walk_profile.cpp: cosine entry, isotropic flights of mean 1/sigma_t, single-scattering
// albedo sigma_s/sigma_t, at most 256 flights; d chosen so Burley's radial CDF matches the walk's
// between its 5th and 98th percentiles). docs/quality.md, "The diffusion profile", gives the error.
#include <array>
#include <glm/vec3.hpp>

#include "marble/render/shader_constants.h"
#include "marble/scene/material.h"

namespace marble {

// d / l (l = 1 / sigma_t, the mean free path) for single-scattering albedo `alpha`: the walk's
// fit, interpolated in u = -log10(1 - alpha) between tabulated rows (clamped outside 0.5..6).
float burleyDOverMeanFreePath(float alpha);

// Burley's d per channel in mm for the material's coefficients.
glm::vec3 burleyShapeD(const Material& m);

// How far the blur reaches each way, mm: kReachInD x the widest d (Burley's radial CDF there:
// 1 - e^-8/4 - 3e^(-8/3)/4 = 0.947; the walk's 0.91-0.94 for the stones in docs/quality.md).
constexpr float kReachInD = 8.0f;
float subsurfaceReachMm(const Material& m);

// The separable kernel: tap i (0..taps) at offset offsetsMm[i] on each side, with weight
// weights[i] per channel (tap 0 once, the others on both sides). The weights are the 1D
// marginal of Burley's 2D profile, P(x) = (K0(|x|/d) + K0(|x|/(3d))) / (4 pi d), integrated over
// each tap's share of the axis, so that the product of the horizontal and vertical passes has
// the 2D profile's variance along each axis (7 d^2). Offsets are spaced quadratically in i
// (dense where the profile is steep): x_i = reach (i / taps)^2.
struct SubsurfaceKernel {
  int taps = 1;
  std::array<float, shader::MAX_TAPS + 1> offsetsMm{};
  std::array<glm::vec3, shader::MAX_TAPS + 1> weights{};
};
SubsurfaceKernel subsurfaceKernel(const glm::vec3& d, float reachMm, int taps);

}  // namespace marble
