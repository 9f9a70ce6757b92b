// The random walk's slab transport cut to one material (slab_transport.h).
#include "marble/scene/slab_transport.h"

#include <algorithm>
#include <cmath>

namespace marble {
namespace {

#include "marble/scene/slab_walk_table.inc"

static_assert(kSlabWalkTauNodes == kSlabTransportNodes, "regenerate slab_walk_table.inc or change the node count");

// Row coordinate of alpha: -log10(1 - alpha), clamped to the table's rows.
float rowCoordinate(float alpha) {
  const double u = -std::log10(std::max(1.0 - static_cast<double>(alpha), 1e-12));
  return std::clamp(static_cast<float>(u), kSlabWalkRowU[0], kSlabWalkRowU[kSlabWalkRows - 1]);
}

// ln T / R_inf at every node for one channel's alpha, linear in the row coordinate.
void fillChannel(SlabTransport& t, int channel, float alpha) {
  const float u = rowCoordinate(alpha);
  int row = 0;
  while (row + 2 < kSlabWalkRows && kSlabWalkRowU[row + 1] < u) ++row;
  const float f = (u - kSlabWalkRowU[row]) / (kSlabWalkRowU[row + 1] - kSlabWalkRowU[row]);
  for (int i = 0; i < kSlabTransportNodes; ++i)
    t.lnT[static_cast<size_t>(i)][channel] = (1.0f - f) * kSlabWalkLnT[row][i] + f * kSlabWalkLnT[row + 1][i];
}

}  // namespace

SlabTransport slabTransportFor(const Material& m) {
  SlabTransport t;
  t.tauMax = kSlabWalkTauMax;
  t.sigmaTMm = glm::max(m.sigma_a_mm, glm::vec3(0.0f)) + glm::max(m.sigma_s_mm, glm::vec3(0.0f));
  for (int c = 0; c < 3; ++c) {
    const float alpha = t.sigmaTMm[c] > 0.0f ? std::max(m.sigma_s_mm[c], 0.0f) / t.sigmaTMm[c] : 0.0f;
    fillChannel(t, c, alpha);
  }
  return t;
}

glm::vec3 slabTransportAt(const SlabTransport& t, float sMm) {
  glm::vec3 out;
  for (int c = 0; c < 3; ++c) {
    const float tau = t.sigmaTMm[c] * std::max(sMm, 0.0f);
    if (!(tau < t.tauMax)) {  // also NaN: no index from it
      out[c] = 0.0f;
      continue;
    }
    const float x = std::sqrt(tau / t.tauMax) * static_cast<float>(kSlabTransportNodes - 1);
    const int i = std::min(static_cast<int>(x), kSlabTransportNodes - 2);
    const float f = x - static_cast<float>(i);
    out[c] = std::exp((1.0f - f) * t.lnT[static_cast<size_t>(i)][c] + f * t.lnT[static_cast<size_t>(i) + 1][c]);
  }
  return out;
}

}  // namespace marble
