// facesHiddenFromEye (render/face_culling.h): which faces the camera's pass may cull.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/render/face_culling.h"

namespace marble {
namespace {

const glm::vec3 kMin(-1.0f), kMax(1.0f);

glm::mat4 viewProj(glm::vec3 eye, float near) {
  return glm::perspective(glm::radians(40.0f), 1.0f, near, 100.0f) *
         glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(FaceCulling, AClosedMeshSeenFromOutsideHidesTheFacesTurnedAway) {
  const glm::mat4 vp = viewProj(glm::vec3(0, 1, 5), 0.1f);
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Outward, vp, kMin, kMax), GLenum{GL_BACK});
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Inward, vp, kMin, kMax), GLenum{GL_FRONT});
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Open, vp, kMin, kMax), GLenum{GL_NONE});
}

TEST(FaceCulling, AMirroringModelMatrixTurnsTheFacesOnScreen) {
  const glm::mat4 vp = viewProj(glm::vec3(0, 1, 5), 0.1f);
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Outward, vp * mirror, kMin, kMax), GLenum{GL_FRONT});
}

TEST(FaceCulling, NothingIsCulledWhereTheNearPlaneCutsTheBox) {
  // The eye 1.5 from the centre, the box's near face 0.5 away: a near plane at 0.6 cuts it open
  // (inside, the far side's inner faces are seen), one at 0.4 does not.
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Outward, viewProj(glm::vec3(0, 0, 1.5f), 0.6f), kMin, kMax),
            GLenum{GL_NONE});
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Outward, viewProj(glm::vec3(0, 0, 1.5f), 0.4f), kMin, kMax),
            GLenum{GL_BACK});
  // The eye inside the box.
  EXPECT_EQ(facesHiddenFromEye(SurfaceWinding::Outward, viewProj(glm::vec3(0, 0, 0.5f), 0.01f), kMin, kMax),
            GLenum{GL_NONE});
}

}  // namespace
}  // namespace marble
