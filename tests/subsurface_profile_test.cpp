// The screen-space blur's diffusion profile against the random walk Cycles' RANDOM_WALK runs in
// the issue's stone (src/marble/render/subsurface_profile.h).
#include "marble/render/subsurface_profile.h"

#include <gtest/gtest.h>

#include "principled_stone.h"

namespace marble {
namespace {

// E[x^2] of the walk's exit points along one axis, over those within the blur's reach (|x| <=
// 6.51 mm, 8 d of red), mm^2: tools/walk_profile.cpp, 400,000 walks per channel (standard error
// under 1 %). The separable blur spreads light along each axis by its kernel's second moment;
// the two passes together, by that along x and y, as the walk does.
constexpr float kWalkAxisSecondMomentMm2[3] = {3.009f, 1.983f, 1.381f};
constexpr float kWalkReachMm = 6.51f;

glm::vec3 axisSecondMoment(const SubsurfaceKernel& k) {
  glm::vec3 sum(0.0f), moment(0.0f);
  for (int i = 0; i <= k.taps; ++i) {
    const float sides = i == 0 ? 1.0f : 2.0f;
    sum += sides * k.weights[i];
    moment += sides * k.weights[i] * k.offsetsMm[i] * k.offsetsMm[i];
  }
  return moment / sum;
}

TEST(SubsurfaceProfile, ReachesAsFarAsTheWalkSpreadsTheIssuesStone) {
  const Material m = test::principledStone();
  EXPECT_NEAR(subsurfaceReachMm(m), kWalkReachMm, 0.05f);
}

// The blur's spread per axis matches the walk's within 15 % (the Burley shape's fit and the
// taps' quadrature), with as many taps as the dragon at 800x800 gets (4) and with all 9. Main
// before session 9 (d = l / 1.05, reach 2 d, weights e^(-x/d) + e^(-x/3d)): 0.21-0.40 of it (checked).
TEST(SubsurfaceProfile, SpreadsLightAsFarAsTheRandomWalk) {
  const Material m = test::principledStone();
  for (int taps : {4, 9}) {
    const glm::vec3 spread = axisSecondMoment(subsurfaceKernel(burleyShapeD(m), subsurfaceReachMm(m), taps));
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(spread[c] / kWalkAxisSecondMomentMm2[c], 1.0f, 0.15f) << "channel " << c << ", " << taps << " taps";
  }
}

// d follows the walk's fit: at marble's albedos, about one mean free path.
TEST(SubsurfaceProfile, BurleyDFollowsTheWalksFit) {
  EXPECT_NEAR(burleyDOverMeanFreePath(0.99f), 0.888f, 1e-3f);
  EXPECT_NEAR(burleyDOverMeanFreePath(0.9f), 0.546f, 1e-3f);
  EXPECT_GT(burleyDOverMeanFreePath(0.999f), burleyDOverMeanFreePath(0.99f));
}

}  // namespace
}  // namespace marble
