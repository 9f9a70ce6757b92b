#include "marble/render/subsurface_profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>

namespace marble {

namespace {
// The walk's 1D marginal (tools/walk_profile.cpp --axis-cdf, 400,000 walks per row, x and y
// counted): kAxisCdf[row][j] is the share of the exits with |x| <= kAxisT[j] mean free paths,
// row at u = kRowU[row] = -log10(1 - alpha).
constexpr float kRowU[] = {0.5f, 1.0f, 1.5f, 2.0f, 2.25f, 2.5f, 2.75f, 3.0f, 3.5f, 4.0f, 5.0f, 6.0f};
constexpr int kRows = static_cast<int>(sizeof(kRowU) / sizeof(kRowU[0]));
constexpr float kAxisT[] = {0, 0.25f, 0.5f, 0.75f, 1, 1.5f, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 40, 48};
constexpr int kTs = static_cast<int>(sizeof(kAxisT) / sizeof(kAxisT[0]));
constexpr float kAxisCdf[kRows][kTs] = {
    {0.00000f, 0.44715f, 0.63376f, 0.74486f, 0.81751f, 0.90171f, 0.94511f, 0.98167f, 0.99353f, 0.99764f, 0.99912f, 0.99987f, 0.99998f, 1.00000f, 1.00000f, 1.00000f, 1.00000f, 1.00000f, 1.00000f, 1.00000f},  // u 0.5
    {0.00000f, 0.35707f, 0.52793f, 0.63976f, 0.71993f, 0.82397f, 0.88596f, 0.94944f, 0.97638f, 0.98881f, 0.99454f, 0.99858f, 0.99961f, 0.99989f, 0.99999f, 1.00000f, 1.00000f, 1.00000f, 1.00000f, 1.00000f},  // u 1
    {0.00000f, 0.30119f, 0.45526f, 0.56204f, 0.64096f, 0.75098f, 0.82232f, 0.90327f, 0.94492f, 0.96727f, 0.97998f, 0.99213f, 0.99675f, 0.99861f, 0.99971f, 0.99994f, 0.99998f, 1.00000f, 1.00000f, 1.00000f},  // u 1.5
    {0.00000f, 0.26637f, 0.40830f, 0.50826f, 0.58460f, 0.69344f, 0.76667f, 0.85726f, 0.90755f, 0.93790f, 0.95721f, 0.97820f, 0.98836f, 0.99354f, 0.99784f, 0.99926f, 0.99975f, 0.99997f, 1.00000f, 1.00000f},  // u 2
    {0.00000f, 0.25891f, 0.39676f, 0.49456f, 0.56813f, 0.67546f, 0.74870f, 0.84035f, 0.89308f, 0.92534f, 0.94641f, 0.97097f, 0.98325f, 0.99010f, 0.99644f, 0.99867f, 0.99950f, 0.99994f, 0.99999f, 1.00000f},  // u 2.25
    {0.00000f, 0.25033f, 0.38377f, 0.47976f, 0.55305f, 0.66032f, 0.73377f, 0.82617f, 0.88035f, 0.91453f, 0.93725f, 0.96464f, 0.97900f, 0.98717f, 0.99509f, 0.99812f, 0.99928f, 0.99991f, 0.99999f, 1.00000f},  // u 2.5
    {0.00000f, 0.24549f, 0.37818f, 0.47279f, 0.54539f, 0.65139f, 0.72468f, 0.81758f, 0.87294f, 0.90821f, 0.93195f, 0.96056f, 0.97609f, 0.98521f, 0.99413f, 0.99762f, 0.99904f, 0.99986f, 0.99999f, 1.00000f},  // u 2.75
    {0.00000f, 0.24296f, 0.37427f, 0.46833f, 0.54065f, 0.64641f, 0.71925f, 0.81241f, 0.86794f, 0.90376f, 0.92802f, 0.95775f, 0.97424f, 0.98377f, 0.99338f, 0.99733f, 0.99891f, 0.99985f, 0.99999f, 1.00000f},  // u 3
    {0.00000f, 0.24070f, 0.37117f, 0.46462f, 0.53683f, 0.64176f, 0.71456f, 0.80788f, 0.86404f, 0.90002f, 0.92476f, 0.95523f, 0.97216f, 0.98232f, 0.99274f, 0.99707f, 0.99881f, 0.99983f, 0.99998f, 1.00000f},  // u 3.5
    {0.00000f, 0.24022f, 0.37042f, 0.46342f, 0.53507f, 0.63992f, 0.71298f, 0.80697f, 0.86309f, 0.89954f, 0.92410f, 0.95478f, 0.97176f, 0.98209f, 0.99265f, 0.99703f, 0.99887f, 0.99983f, 0.99998f, 1.00000f},  // u 4
    {0.00000f, 0.24044f, 0.37002f, 0.46320f, 0.53502f, 0.63996f, 0.71213f, 0.80535f, 0.86127f, 0.89775f, 0.92280f, 0.95380f, 0.97122f, 0.98164f, 0.99242f, 0.99685f, 0.99873f, 0.99984f, 0.99998f, 1.00000f},  // u 5
    {0.00000f, 0.23975f, 0.36884f, 0.46158f, 0.53376f, 0.63826f, 0.71141f, 0.80500f, 0.86086f, 0.89754f, 0.92231f, 0.95347f, 0.97085f, 0.98150f, 0.99223f, 0.99685f, 0.99875f, 0.99981f, 0.99998f, 1.00000f},  // u 6
};

// The walk's share inside the centred square |x|, |y| <= kSquareH[j] mean free paths, per albedo row
// kSquareRowU (the same walk, its own run outside the project: /work/s26-direct-scratch/tools/
// coretab2.py, 400,000 walks per row, seed 7; its marginal agrees with kAxisCdf within 0.002).
constexpr float kSquareRowU[] = {0.5f, 1.0f, 2.0f, 3.0f, 4.0f, 6.0f};
constexpr int kSquareRows = static_cast<int>(sizeof(kSquareRowU) / sizeof(kSquareRowU[0]));
constexpr float kSquareH[] = {0.25f, 0.5f, 0.75f, 1.0f, 1.5f, 2.0f, 3.0f, 4.0f, 6.0f, 8.0f, 12.0f};
constexpr int kSquareHs = static_cast<int>(sizeof(kSquareH) / sizeof(kSquareH[0]));
constexpr float kSquareShare[kSquareRows][kSquareHs] = {
    {0.2932f, 0.4841f, 0.6172f, 0.7125f, 0.8346f, 0.9026f, 0.9659f, 0.9874f, 0.9983f, 0.9998f, 1.0000f},
    {0.2147f, 0.3708f, 0.4913f, 0.5859f, 0.7225f, 0.8117f, 0.9109f, 0.9569f, 0.9893f, 0.9972f, 0.9998f},
    {0.1489f, 0.2644f, 0.3590f, 0.4388f, 0.5625f, 0.6556f, 0.7772f, 0.8505f, 0.9269f, 0.9618f, 0.9881f},
    {0.1324f, 0.2370f, 0.3232f, 0.3958f, 0.5123f, 0.5992f, 0.7189f, 0.7951f, 0.8823f, 0.9277f, 0.9704f},
    {0.1300f, 0.2328f, 0.3186f, 0.3904f, 0.5060f, 0.5917f, 0.7112f, 0.7875f, 0.8754f, 0.9223f, 0.9677f},
    {0.1295f, 0.2321f, 0.3172f, 0.3890f, 0.5042f, 0.5903f, 0.7096f, 0.7857f, 0.8742f, 0.9213f, 0.9670f},
};

// The row pair and weight for albedo alpha.
void rowOf(float alpha, int& row, float& frac) {
  const float u = -std::log10(std::max(1.0f - alpha, 1e-7f));
  if (u <= kRowU[0]) {
    row = 0, frac = 0.0f;
    return;
  }
  for (int i = 1; i < kRows; ++i) {
    if (u <= kRowU[i]) {
      row = i - 1, frac = (u - kRowU[i - 1]) / (kRowU[i] - kRowU[i - 1]);
      return;
    }
  }
  row = kRows - 2, frac = 1.0f;
}

float rowShare(int row, float t) {
  if (t >= kAxisT[kTs - 1]) return 1.0f;
  int j = 1;
  while (kAxisT[j] < t) ++j;
  const float f = (t - kAxisT[j - 1]) / (kAxisT[j] - kAxisT[j - 1]);
  return kAxisCdf[row][j - 1] + f * (kAxisCdf[row][j] - kAxisCdf[row][j - 1]);
}
}  // namespace

float walkAxisShare(float alpha, float t) {
  if (t <= 0.0f) return 0.0f;
  int row;
  float frac;
  rowOf(alpha, row, frac);
  return (1.0f - frac) * rowShare(row, t) + frac * rowShare(row + 1, t);
}

float walkSquareShare(float alpha, float h) {
  if (h <= 0.0f) return 0.0f;
  const float u = -std::log10(std::max(1.0f - alpha, 1e-7f));
  int row = kSquareRows - 2;
  float frac = 1.0f;
  if (u <= kSquareRowU[0]) {
    row = 0, frac = 0.0f;
  } else {
    for (int i = 1; i < kSquareRows; ++i) {
      if (u <= kSquareRowU[i]) {
        row = i - 1, frac = (u - kSquareRowU[i - 1]) / (kSquareRowU[i] - kSquareRowU[i - 1]);
        break;
      }
    }
  }
  auto at = [&](int r) {
    if (h <= kSquareH[0]) return kSquareShare[r][0] * h / kSquareH[0];
    if (h >= kSquareH[kSquareHs - 1]) return kSquareShare[r][kSquareHs - 1];
    int j = 1;
    while (kSquareH[j] < h) ++j;
    const float f = (h - kSquareH[j - 1]) / (kSquareH[j] - kSquareH[j - 1]);
    return kSquareShare[r][j - 1] + f * (kSquareShare[r][j] - kSquareShare[r][j - 1]);
  };
  return (1.0f - frac) * at(row) + frac * at(row + 1);
}

WalkShape walkShape(const Material& m) {
  const glm::vec3 sigmaT = glm::max(m.sigma_a_mm + m.sigma_s_mm, glm::vec3(1e-4f));
  return {1.0f / sigmaT, m.sigma_s_mm / sigmaT};
}

float subsurfaceReachMm(const Material& m) {
  const WalkShape w = walkShape(m);
  float reach = 0.0f;
  for (int c = 0; c < 3; ++c) {
    // The t where 1 - share falls to kTailShare: the share rises with t, so bisect.
    float lo = 0.0f, hi = kAxisT[kTs - 1];
    for (int k = 0; k < 40; ++k) {
      const float mid = 0.5f * (lo + hi);
      (1.0f - walkAxisShare(w.albedo[c], mid) > kTailShare ? lo : hi) = mid;
    }
    reach = std::max(reach, hi * w.meanFreePathMm[c]);
  }
  return reach;
}

float walkRingRadiusMm(const WalkShape& walk) {
  const glm::vec3 luminance{0.2126f, 0.7152f, 0.0722f};
  const float last = kSquareH[kSquareHs - 1];
  float radius = 0.0f;
  for (int c = 0; c < 3; ++c) {
    // The share rises with h: bisect for 3/4 (held at the table's last h, 12 mean free paths).
    float lo = 0.0f, hi = last;
    for (int k = 0; k < 40; ++k) {
      const float mid = 0.5f * (lo + hi);
      (walkSquareShare(walk.albedo[c], mid) < 0.75f ? lo : hi) = mid;
    }
    radius += luminance[c] * hi * walk.meanFreePathMm[c] * 2.0f / std::sqrt(std::numbers::pi_v<float>);
  }
  return radius;
}

SubsurfaceKernel subsurfaceKernel(const WalkShape& walk, float reachMm, int taps, float coreHalfWidthMm) {
  SubsurfaceKernel k;
  k.taps = std::clamp(taps, 1, static_cast<int>(shader::MAX_TAPS));
  for (int i = 0; i <= k.taps; ++i) {
    const float f = static_cast<float>(i) / static_cast<float>(k.taps);
    k.offsetsMm[i] = reachMm * f * f;
  }
  for (int i = 0; i <= k.taps; ++i) {
    // Tap i stands for the part of the axis nearer to it than to its neighbours (tap 0: both
    // sides of the centre, counted once; the last: out to the reach). walkAxisShare counts both
    // sides, so a tap off the centre takes half of its band's share.
    const float a = i == 0 ? 0.0f : 0.5f * (k.offsetsMm[i - 1] + k.offsetsMm[i]);
    const float b = i == k.taps ? k.offsetsMm[i] : 0.5f * (k.offsetsMm[i] + k.offsetsMm[i + 1]);
    for (int c = 0; c < 3; ++c) {
      const float l = std::max(walk.meanFreePathMm[c], 1e-6f);
      const float band = walkAxisShare(walk.albedo[c], b / l) - walkAxisShare(walk.albedo[c], a / l);
      k.weights[i][c] = (i == 0 ? 1.0f : 0.5f) * band;
    }
  }
  // The profile's density at each tap, one side of the axis: its band's share over the band's
  // width (tap 0's band spans both sides, so half of it over half its width).
  std::array<glm::vec3, shader::MAX_TAPS + 1> density{};
  for (int i = 0; i <= k.taps; ++i) {
    const float a = i == 0 ? 0.0f : 0.5f * (k.offsetsMm[i - 1] + k.offsetsMm[i]);
    const float b = i == k.taps ? k.offsetsMm[i] : 0.5f * (k.offsetsMm[i] + k.offsetsMm[i + 1]);
    density[i] = (i == 0 ? 0.5f : 1.0f) * k.weights[i] / std::max(b - a, 1e-6f);
  }
  for (int i = 1; i <= k.taps; ++i) {
    const int lo = i < k.taps ? i : i - 1;  // the last tap takes the slope before it
    const float dx = std::max(k.offsetsMm[lo + 1] - k.offsetsMm[lo], 1e-6f);
    for (int c = 0; c < 3; ++c) {
      const float d0 = std::max(density[lo][c], 1e-30f), d1 = std::max(density[lo + 1][c], 1e-30f);
      k.decayPerMm[i][c] = std::max(std::log(d0 / d1) / dx, 0.0f);
    }
  }
  // The core (SubsurfaceKernel) at the texel's square, half-width h = coreHalfWidthMm: the walk's
  // shares there, M along the axis (|x| <= h) and Q in the square. The taps within h all read about
  // the centre texel (bilinearly, the first at a texel or less at the scenes' scales), so the core
  // is taken from the centre tap's weight, kept within [0, its share] so no weight goes negative
  // (few taps or h past the table: none).
  const float h = coreHalfWidthMm;
  for (int c = 0; c < 3; ++c) {
    float total = k.weights[0][c];
    for (int i = 1; i <= k.taps; ++i) total += 2.0f * k.weights[i][c];
    if (total <= 0.0f || h <= 0.0f) continue;
    const float l = std::max(walk.meanFreePathMm[c], 1e-6f);
    const float M = walkAxisShare(walk.albedo[c], h / l);
    const float Q = walkSquareShare(walk.albedo[c], h / l);
    const float core = std::clamp((Q - M * M) / std::max(1.0f - 2.0f * M + Q, 1e-6f), 0.0f, k.weights[0][c] / total);
    k.core[c] = core;
    k.weights[0][c] -= core * total;
    for (int i = 0; i <= k.taps; ++i) k.weights[i][c] /= 1.0f - core;
  }
  return k;
}

}  // namespace marble
