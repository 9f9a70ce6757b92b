#pragma once
// The diffusion profile the `marble` mode's screen-space blur spreads entering light with
// (shaders/subsurface_blur.frag.glsl): its width per channel, its reach, and the separable taps'
// offsets and weights. Pure CPU; the blur pass uploads what this computes.
//
// Shape: the 1D marginal of the random walk Cycles' RANDOM_WALK runs in the same stone, tabulated
// (tools/walk_profile.cpp: cosine entry, isotropic flights of mean 1/sigma_t, single-scattering
// albedo sigma_s/sigma_t, at most 256 flights; section 3 of its output). Since session 18; before,
// Burley's normalized diffusion (Christensen & Burley 2015) with d fitted to the walk's 5th-98th
// percentiles and cut at 8 d of red (6.5 mm in the stone): right near the entry, but its
// tail e^(-r/(3d)) falls 2-4x faster than the walk's, whose light past a straight edge by 6.5 mm
// (1.8 % of red, 0.26 % of blue) is what keeps a side-lit statue's shade red in Cycles
// (docs/quality.md, "Eighteenth session: the side-lit shade").
#include <array>
#include <glm/vec3.hpp>

#include "marble/render/shader_constants.h"
#include "marble/scene/material.h"

namespace marble {

// The walk's 1D marginal: the share of the light that entered at a point and leaves the stone
// with |x| <= t mean free paths (along one axis, x the signed distance), for single-scattering
// albedo `alpha`; interpolated linearly in u = -log10(1 - alpha) between the tabulated rows
// (clamped outside 0.5..6) and in t (1 beyond the table's last t, 48). Sampling error under 0.1 %
// of the light per value (400,000 walks per row).
float walkAxisShare(float alpha, float t);

// The stone's walk per channel: mean free path 1 / sigma_t (mm) and single-scattering albedo.
struct WalkShape {
  glm::vec3 meanFreePathMm{1.0f};
  glm::vec3 albedo{0.0f};
  bool operator==(const WalkShape&) const = default;
};
WalkShape walkShape(const Material& m);

// How far the blur reaches each way, mm: where the widest channel's walk leaves kTailShare of
// its light farther out along the axis (both sides together; the stone: 16.2 mm, red).
constexpr float kTailShare = 0.002f;
float subsurfaceReachMm(const Material& m);

// The separable kernel: tap i (0..taps) at offset offsetsMm[i] on each side, with weight
// weights[i] per channel (tap 0 once, the others on both sides). The weights are the walk's 1D
// marginal integrated over each tap's share of the axis (walkAxisShare), so each pass spreads
// light along its axis as the walk does, out to the reach; the light beyond is left out (the
// blur normalizes by the weights it sums). Offsets are spaced quadratically in i (dense where the
// profile is steep): x_i = reach (i / taps)^2.
// decayPerMm[i] (i >= 1): how fast the profile falls past tap i, per channel: the log slope of
// its density between tap i and tap i + 1 (the last tap: between the last two), each tap's density
// its band's share over the band's width; >= 0. The blur weighs a tap whose 3D distance d from the
// centre exceeds its offset x (a tap on another surface at another depth, across a silhouette or a
// step) by exp(-decay (d - x)): the profile read at d instead of x, extrapolated along its local
// log slope (shaders/subsurface_blur.frag.glsl; docs/quality.md, "Twenty-sixth session: the
// blur's taps at their 3D distance"). decayPerMm[0] is 0 (the centre tap is the centre).
struct SubsurfaceKernel {
  int taps = 1;
  std::array<float, shader::MAX_TAPS + 1> offsetsMm{};
  std::array<glm::vec3, shader::MAX_TAPS + 1> weights{};
  std::array<glm::vec3, shader::MAX_TAPS + 1> decayPerMm{};
};
SubsurfaceKernel subsurfaceKernel(const WalkShape& walk, float reachMm, int taps);

}  // namespace marble
