// trianglesGlMayDraw (render/screen_cull.h): the triangles dropped before GL are those of the
// culled sense by more than the slack; the rest keep their order. GL's side (that no triangle GL
// draws is dropped) is screen_cull_gl_test.cpp.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/gl/software_rasterizer.h"
#include "marble/render/screen_cull.h"

namespace marble {
namespace {

// An orthographic view of z = 0 onto a 100 x 100 viewport: one unit of x or y is one pixel.
const glm::mat4 kPixels = glm::ortho(-50.0f, 50.0f, -50.0f, 50.0f, -1.0f, 1.0f);

std::vector<uint32_t> kept(const std::vector<glm::vec3>& p, const std::vector<uint32_t>& idx, CulledSense sense,
                           double slack = kScreenCullSlackPixels, const glm::mat4& m = kPixels) {
  Mesh mesh;
  mesh.positions = p;
  mesh.indices = idx;
  std::vector<uint32_t> out(idx.size());
  std::vector<float> scratch;
  out.resize(3 * trianglesGlMayDraw(ScreenCullMesh(mesh), m, 100, 100, sense, out.data(), scratch, slack));
  return out;
}

TEST(ScreenCull, DropsTheClockwiseTrianglesAndKeepsTheOrder) {
  // 0: counter-clockwise on screen, 1: clockwise, 2: counter-clockwise.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {-20, -20, 0}, {-10, -20, 0}, {-20, -10, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 1, 3, 4, 5};
  EXPECT_EQ(kept(p, idx, CulledSense::Clockwise), (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(kept(p, idx, CulledSense::CounterClockwise), (std::vector<uint32_t>{0, 2, 1}));
}

TEST(ScreenCull, KeepsATriangleWithinTheSlackOfTurning) {
  // Clockwise by a doubled area of 10 x 0.001 = 0.01 pixel^2: the slack's bound for these edges is
  // 2 / 128 x 20.001 + 8 / 128^2 = 0.31, so a corner moved by 1/512 pixel could turn it. Control:
  // with no slack it is dropped.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {0, 0.001f, 0}, {10, 0, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2};
  EXPECT_EQ(kept(p, idx, CulledSense::Clockwise).size(), 3u);
  EXPECT_EQ(kept(p, idx, CulledSense::Clockwise, 0.0).size(), 0u);
  // Clockwise by 10 x 0.5 = 5 pixel^2: beyond the slack, dropped.
  const std::vector<glm::vec3> q = {{0, 0, 0}, {0, 0.5f, 0}, {10, 0, 0}};
  EXPECT_EQ(kept(q, idx, CulledSense::Clockwise).size(), 0u);
}

TEST(ScreenCull, KeepsTrianglesWithACornerOutsideTheViewVolume) {
  // Clockwise, but a corner beyond the right edge (GL clips the triangle into new ones), or behind
  // the near plane of a perspective view.
  const std::vector<uint32_t> idx = {0, 1, 2};
  EXPECT_EQ(kept({{0, 0, 0}, {0, 10, 0}, {60, 0, 0}}, idx, CulledSense::Clockwise).size(), 3u);
  EXPECT_EQ(kept({{0, 0, 0}, {0, 10, 0}, {40, 0, 0}}, idx, CulledSense::Clockwise).size(), 0u);  // control
  const glm::mat4 eye = glm::perspective(glm::radians(60.0f), 1.0f, 1.0f, 100.0f) *
                        glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
  EXPECT_EQ(kept({{0, 0, 0}, {0, 1, 0}, {1, 0, 4.5f}}, idx, CulledSense::Clockwise, kScreenCullSlackPixels, eye).size(),
            3u);
  EXPECT_EQ(kept({{0, 0, 0}, {0, 1, 0}, {1, 0, 3.0f}}, idx, CulledSense::Clockwise, kScreenCullSlackPixels, eye).size(),
            0u);  // control: all three in view
}

}  // namespace
TEST(SoftwareRasterizer, TellsMesasAndGooglesCpuRasterizersFromGpus) {
  EXPECT_TRUE(gl::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(gl::isSoftwareRenderer("zink (llvmpipe (LLVM 15.0.6, 256 bits))"));
  EXPECT_TRUE(gl::isSoftwareRenderer("softpipe"));
  EXPECT_TRUE(gl::isSoftwareRenderer("Google SwiftShader"));
  EXPECT_FALSE(gl::isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(gl::isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.52)"));
  EXPECT_FALSE(gl::isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  EXPECT_FALSE(gl::isSoftwareRenderer(nullptr));
}

}  // namespace marble
