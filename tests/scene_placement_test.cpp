// Placing the light and camera by angles (--light, --camera, the viewer's preset buttons).
#include <gtest/gtest.h>

#include "marble/scene/placement.h"

using namespace marble;

TEST(Placement, LightKeepsItsDistanceAndBackIsBehindTheObjectFromTheCamera) {
  Scene s;
  s.camera.position = {4.0f, 0.0f, 0.0f};  // the camera on +X
  const float d = glm::length(s.light.position);
  placeLight(s, findPreset(lightPresets(), "back")->azimuthDeg, 0.0f);
  EXPECT_NEAR(glm::length(s.light.position), d, 1e-4f);
  EXPECT_NEAR(s.light.position.x, -d, 1e-3f) << "opposite the camera";
  placeLight(s, 0.0f, 0.0f);
  EXPECT_NEAR(s.light.position.x, d, 1e-3f) << "azimuth 0: on the camera's side";
  placeLight(s, 0.0f, 90.0f);
  EXPECT_EQ(s.light.position, glm::vec3(0.0f, d, 0.0f)) << "top: straight above";
}

TEST(Placement, CameraAnglesAboutTheTarget) {
  Scene s;
  s.camera.target = {0.0f, 0.5f, 0.0f};
  placeCamera(s, 90.0f, 0.0f, 3.0f);
  EXPECT_NEAR(s.camera.position.x, 3.0f, 1e-5f);
  EXPECT_NEAR(s.camera.position.y, 0.5f, 1e-5f);
  EXPECT_NEAR(cameraAzimuthDeg(s.camera), 90.0f, 1e-3f);
  placeCamera(s, 0.0f, 95.0f);  // clamped short of the pole, distance kept
  EXPECT_NEAR(glm::length(s.camera.position - s.camera.target), 3.0f, 1e-4f);
  EXPECT_GT(glm::length(glm::cross(glm::normalize(s.camera.position - s.camera.target), s.camera.up)), 0.01f);
}

TEST(Placement, SizeMmIsTwiceMmPerUnit) {
  Scene s;
  setObjectSizeMm(s, 50.0f);
  EXPECT_EQ(s.mm_per_unit, 25.0f);
  EXPECT_EQ(objectSizeMm(s), 50.0f);
}
