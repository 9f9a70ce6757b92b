// The screen rectangle the screen passes are scissored to (src/marble/render/screen_rect.h).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/render/screen_rect.h"

using namespace marble;

namespace {
glm::mat4 lookingDownMinusZ(float distance) {
  const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  return proj * glm::lookAt(glm::vec3(0, 0, distance), glm::vec3(0), glm::vec3(0, 1, 0));
}
}  // namespace

TEST(ScreenRect, BoxInFrontProjectsToACentredRectangleWithMargin) {
  const ScreenRect r = projectedBounds(glm::vec3(-1), glm::vec3(1), lookingDownMinusZ(5.0f), 200, 200, 2);
  EXPECT_FALSE(r.empty());
  // Centred: equal space left and right, below and above.
  EXPECT_NEAR(r.x, 200 - (r.x + r.width), 1);
  EXPECT_NEAR(r.y, 200 - (r.y + r.height), 1);
  // The near face (z = 1, distance 4) spans tan(30 deg) * 4 = 2.31 units of half-height:
  // 1 / 2.31 * 100 px = 43.3 px from the centre, plus the 2 px margin.
  EXPECT_NEAR(r.width / 2.0, 43.3 + 2.0, 1.5);
}

TEST(ScreenRect, CornerBehindTheCameraGivesTheWholeTarget) {
  const ScreenRect r = projectedBounds(glm::vec3(-1), glm::vec3(1), lookingDownMinusZ(0.5f), 320, 240);
  EXPECT_EQ(r, (ScreenRect{0, 0, 320, 240}));
}

TEST(ScreenRect, IsClampedToTheTarget) {
  const ScreenRect r = projectedBounds(glm::vec3(-1), glm::vec3(1), lookingDownMinusZ(1.8f), 100, 80);
  EXPECT_GE(r.x, 0);
  EXPECT_GE(r.y, 0);
  EXPECT_LE(r.x + r.width, 100);
  EXPECT_LE(r.y + r.height, 80);
}

TEST(ScreenRect, OffScreenBoxIsEmpty) {
  const glm::mat4 mvp = lookingDownMinusZ(5.0f) * glm::translate(glm::mat4(1.0f), glm::vec3(50, 0, 0));
  EXPECT_TRUE(projectedBounds(glm::vec3(-1), glm::vec3(1), mvp, 100, 100).empty());
}

TEST(ScreenRect, ScaledDownRoundsOutward) {
  EXPECT_EQ(scaledDown({3, 4, 5, 6}, 2), (ScreenRect{1, 2, 3, 3}));  // pixels 3..7 -> 1..3, 4..9 -> 2..4
  EXPECT_EQ(scaledDown({0, 0, 801, 600}, 2), (ScreenRect{0, 0, 401, 300}));
  EXPECT_EQ(scaledDown({10, 20, 30, 40}, 1), (ScreenRect{10, 20, 30, 40}));
}
