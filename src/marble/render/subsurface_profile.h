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
//
// The core: the walk's exits are radially symmetric, and a product of its marginals (what two 1D
// passes give) puts less of the light near the entry than the walk does: inside a blur texel's
// square (half-width h; the dragon's scenes: 0.335 mm) the walk leaves Q of its light
// (walkSquareShare), the product of two marginal shares M only M^2 (the stone: 0.21, 0.28,
// 0.33 against 0.11, 0.18, 0.23; a deficit of about 0.1 of the light at every h from 0.3 to 2 mm).
// So the kernel is split, K = core delta + (1 - core) m_r x m_r: `core` of the light leaves at
// the entry's own texel (the second pass adds it from the lighting pass's texel), the rest goes
// through both passes with the residual marginal m_r = (m - core delta) / (1 - core) (`weights`:
// the centre tap's weight less core, all over 1 - core). The marginal along either axis is still
// the walk's m (straight edges and the shade past them keep their profile), and core is chosen so
// that the texel square's share, core + (1 - core) M_r^2, is the walk's Q: core = (Q - M^2) /
// (1 - 2 M + Q) (the stone at 0.335 mm: 0.18, 0.24, 0.28). Approximation: the deficit is
// matched at the texel's scale only; at 2-6 texels the residual product still holds 0.07-0.1 less
// than the walk's square (docs/quality.md, "Twenty-sixth session: the separable blur's core").
//
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
  glm::vec3 core{0.0f};
  std::array<glm::vec3, shader::MAX_TAPS + 1> decayPerMm{};
};

// The walk's share of its exits inside the centred square |x|, |y| <= h mean free paths, for
// single-scattering albedo `alpha` (tools/walk_profile.cpp's walk, 400,000 walks per row;
// interpolated as walkAxisShare; h from 0.25 to 3 mean free paths, linear to 0 below, held above).
float walkSquareShare(float alpha, float h);
// The radius (mm) of the ring that stands for the outer half of the walk's light where the lighting
// pass spreads a hidden lit face's light (shaders/mirror_lit_face.glsl, lit_face_spread): per
// channel, the half-width h where walkSquareShare reaches 3/4 (the outer half's median), as the radius
// of the disc of the square's area (h 2 / sqrt(pi)); the channels weighed by luminance (Rec. 709:
// the light is near white, SSIM reads luminance). The stone: 2.06 mm.
float walkRingRadiusMm(const WalkShape& walk);
// coreHalfWidthMm: half a blur texel at the object's distance (the square the core is matched in);
// 0: no core, the product of marginals alone.
SubsurfaceKernel subsurfaceKernel(const WalkShape& walk, float reachMm, int taps, float coreHalfWidthMm);

}  // namespace marble
