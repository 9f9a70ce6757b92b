// The random walk's slab transport (marble/scene/slab_transport.h) against Blender Cycles 3.4.1's
// own renders of the same slabs: the issue's stone (base colour 0.87, 0.85, 0.8, radius 17, 12,
// 8 mm, ior 1.5) as a 200 mm wide box s mm thick, a sun of strength pi straight behind it, seen
// head-on (tools/cycles_reference.py, 64x64, 512 samples, --box; the mean of the centre 16x16
// pixels; docs/quality.md, "Transmission from a random walk"). There the radiance leaving the
// far face is the walk's transmitted fraction T(s) itself; marble draws albedo * T(s) / R_inf.
// The dipole slab transport this replaced (Jensen et al. 2001's R_d over a plane s away, over its
// total, times the albedo) gives 0.472, 0.353, 0.246 at 2 mm and 0.094, 0.032, 0.0076 at 10 mm: it
// fails the first test by 25-50 % in red and green.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "marble/scene/material_scattering.h"
#include "marble/scene/slab_transport.h"
#include "principled_stone.h"

namespace marble {
namespace {

Material issueStone() { return test::principledStone(); }

struct CyclesSlab {
  float mm;
  glm::vec3 radiance;
  float noise;  // standard error of the 256-pixel mean (pixel spread / 16)
};

TEST(SlabTransport, MatchesCyclesSlabRenders) {
  const Material m = issueStone();
  const SlabTransport t = slabTransportFor(m);
  const CyclesSlab slabs[] = {{2.0f, {0.33109f, 0.25683f, 0.21579f}, 0.0019f},
                              {5.0f, {0.16069f, 0.10995f, 0.07219f}, 0.0018f},
                              {10.0f, {0.07454f, 0.03386f, 0.01143f}, 0.0019f},
                              // Here the cap on the walk's length rules: uncapped, red would be 0.024.
                              {20.0f, {0.01274f, 0.00161f, 0.00007f}, 0.00125f}};
  for (const CyclesSlab& c : slabs) {
    const glm::vec3 marble = m.base_color * slabTransportAt(t, c.mm);
    // Three standard errors of the render, plus 4 % for the table's own Monte Carlo noise, its
    // interpolation between albedo rows, and R_inf against the base colour (Chiang's fit, ~1 %).
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(marble[ch], c.radiance[ch], 3.0f * c.noise + 0.04f * c.radiance[ch]) << c.mm << " mm, channel " << ch;
    std::cout << "[          ] " << c.mm << " mm: marble " << marble.r << " " << marble.g << " " << marble.b << ", Cycles "
              << c.radiance.r << " " << c.radiance.g << " " << c.radiance.b << "\n";
  }
}

TEST(SlabTransport, FallsWithThicknessAndEndsAtTheTable) {
  const SlabTransport t = slabTransportFor(issueStone());
  glm::vec3 previous = slabTransportAt(t, 0.0f);
  for (int c = 0; c < 3; ++c) EXPECT_GT(previous[c], 1.0f) << "a vanishing slab lets through more than the stone reflects";
  for (float s = 0.5f; s < 60.0f; s += 0.5f) {
    const glm::vec3 now = slabTransportAt(t, s);
    for (int c = 0; c < 3; ++c) EXPECT_LE(now[c], previous[c] * 1.001f) << s << " mm, channel " << c;
    previous = now;
  }
  // Past tau_max (64 mean free paths; blue's sigma_t is 2.07 per mm, red's 1.25) nothing.
  EXPECT_EQ(slabTransportAt(t, 60.0f).b, 0.0f);
  EXPECT_GT(slabTransportAt(t, 40.0f).r, 0.0f);
  EXPECT_EQ(slabTransportAt(t, 60.0f).r, 0.0f);
}

// Through the thickest stone the table holds (tau 50-64, the thick body's chords: red's 40-51 mm,
// blue's 24-31 mm) too few of the table's sampled walks got through, and those nodes come from the
// same capped walk solved without sampling (tools/slab_walk_table.py, capped_walk_transmission).
// Under Cycles' cap of 256 flights a walk spreads only about 13 optical units in depth, so ln T
// bends down ever faster there; the straight line in ln T that continued the resolved nodes before
// (session 23) kept the slope constant and read 1.1-15x too much light at tau 49-64.
TEST(SlabTransport, TheCappedWalksTailFallsFasterThanAnExponential) {
  const SlabTransport t = slabTransportFor(issueStone());
  const auto tauAt = [&](int i) {
    const float f = static_cast<float>(i) / static_cast<float>(kSlabTransportNodes - 1);
    return t.tauMax * f * f;
  };
  for (int c = 0; c < 3; ++c) {
    float previousSlope = 0.0f;
    for (int i = kSlabTransportNodes - 5; i + 1 < kSlabTransportNodes; ++i) {
      const float slope = (t.lnT[static_cast<size_t>(i) + 1][c] - t.lnT[static_cast<size_t>(i)][c]) / (tauAt(i + 1) - tauAt(i));
      EXPECT_LT(slope, -0.2f) << "node " << i << ", channel " << c;
      if (i > kSlabTransportNodes - 5) {
        EXPECT_LT(slope, previousSlope - 0.005f) << "the tail bends down: node " << i << ", channel " << c;
      }
      previousSlope = slope;
    }
  }
}

TEST(SlabTransport, MoreAbsorptionLetsLessThrough) {
  // The same extinction, a lower single-scattering albedo: less through, relative to what each
  // reflects, from a few mean free paths on (through a thin slab the walk is short and absorption
  // takes less from T than from R_inf, so the ratio may rise there, rightly).
  Material clear = issueStone(), dark = issueStone();
  dark.sigma_a_mm *= 20.0f;
  dark.sigma_s_mm -= dark.sigma_a_mm - clear.sigma_a_mm;
  const SlabTransport a = slabTransportFor(clear), b = slabTransportFor(dark);
  for (float s : {5.0f, 10.0f, 20.0f})
    for (int c = 0; c < 3; ++c) EXPECT_LT(slabTransportAt(b, s)[c], slabTransportAt(a, s)[c]) << s << " mm, channel " << c;
}

}  // namespace
}  // namespace marble
