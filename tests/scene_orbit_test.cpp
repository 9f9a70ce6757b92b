#include <gtest/gtest.h>

#include "marble/scene/orbit.h"

using namespace marble;

TEST(SceneOrbit, RoundTripsAPosition) {
  const glm::vec3 p(1.0f, 2.0f, 3.0f);
  const Orbit o = Orbit::fromPosition(p);
  EXPECT_NEAR(glm::length(o.position() - p), 0.0f, 1e-4f);
}

TEST(SceneOrbit, PitchIsClampedAndZoomStaysPositive) {
  Orbit o;
  o.rotate(0, 500);
  EXPECT_LE(o.pitch_deg, 89.0f);
  for (int i = 0; i < 1000; ++i) o.zoom(1);
  EXPECT_GE(o.distance, Orbit::kMinDistance);
  for (int i = 0; i < 1000; ++i) o.zoom(-1);
  EXPECT_LE(o.distance, Orbit::kMaxDistance);
}

TEST(SceneOrbit, PanMovesTheTargetSideways) {
  Orbit o = Orbit::fromPosition({0, 0, 4});
  o.pan(0.5f, 0);
  EXPECT_GT(std::abs(o.target.x), 1.0f);
  EXPECT_NEAR(o.target.y, 0.0f, 1e-5f);
}
