// The light-depth pass culls the faces no ray from the light meets first (render/face_culling.h)
// in its depth map and reflective shadow map, where the mesh is closed and the light outside its
// bounding box: every map must equal, bit for bit, the one drawn with both faces
// (LightDepthPass::setCullsHiddenFaces(false)) -- from a point light, a directional light, with a
// mirroring model matrix, and with the light inside a closed mesh, where the inner faces are what
// it meets and nothing may be culled. The entry and exit layers draw both faces either way.
// Negative controls (by hand, session 22): culling the other faces (every outside case fails), and
// facesHiddenFromEye without its bounding-box test (the light inside the cube meets nothing where
// its walls were culled), each fail their test.
#include <gtest/gtest.h>

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_support.h"
#include "marble/render/face_culling.h"
#include "marble/render/light_depth_pass.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kMapSize = 256;

std::vector<float> texels(GLuint texture, GLenum format, int channels, int size) {
  std::vector<float> v(static_cast<size_t>(size) * size * channels);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
  return v;
}

struct LightMaps {
  std::vector<float> distance, depth, bouncePosition, bounceNormal, layers;
};

LightMaps lightMaps(const Mesh& mesh, const glm::mat4& model, const Light& light, bool cull) {
  LightDepthPass pass(ShaderLibrary(), kMapSize);
  pass.setCullsHiddenFaces(cull);
  const GpuMesh gpu(mesh);
  pass.run(gpu, model, lightMatrices(light));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const int b = pass.bounceSize(), l = kMapSize / 4;
  return {texels(pass.distanceTexture(), GL_RG, 2, kMapSize), texels(pass.depthTexture(), GL_DEPTH_COMPONENT, 1, kMapSize),
          texels(pass.bouncePositionTexture(), GL_RGBA, 4, b), texels(pass.bounceNormalTexture(), GL_RGBA, 4, b),
          texels(pass.layersTexture(), GL_RG, 2, l)};
}

size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += a[i] != b[i];
  return n;
}

// expectCulled: whether the case is one where faces are culled (else the test would prove nothing).
void expectCullingChangesNothing(const Mesh& mesh, const glm::mat4& model, const Light& light, bool expectCulled,
                                 size_t minCovered) {
  glContext();
  const GpuMesh gpu(mesh);
  EXPECT_EQ(facesHiddenFromEye(gpu.winding(), lightMatrices(light).viewProj * model, gpu.boundsMin(), gpu.boundsMax()) !=
                GLenum{GL_NONE},
            expectCulled);
  const LightMaps culled = lightMaps(mesh, model, light, true);
  const LightMaps both = lightMaps(mesh, model, light, false);
  size_t covered = 0;
  for (size_t i = 0; i < both.depth.size(); ++i) covered += both.depth[i] < 1.0f;
  EXPECT_GE(covered, minCovered) << "the light must meet the mesh";
  EXPECT_EQ(differing(culled.distance, both.distance), 0u);
  EXPECT_EQ(differing(culled.depth, both.depth), 0u);
  EXPECT_EQ(differing(culled.bouncePosition, both.bouncePosition), 0u);
  EXPECT_EQ(differing(culled.bounceNormal, both.bounceNormal), 0u);
  EXPECT_EQ(differing(culled.layers, both.layers), 0u);
}

}  // namespace

TEST(LightFaceCulling, APointLightOutsideTheSculptureKeepsEveryMap) {
  expectCullingChangesNothing(builtinMesh(kDefaultBuiltinMesh), glm::mat4(1.0f), Light{}, true, 5000);
}

TEST(LightFaceCulling, ADirectionalLightKeepsEveryMap) {
  Light light;
  light.type = LightType::Directional;
  light.position = glm::vec3(-1.0f, 2.0f, 1.5f);
  expectCullingChangesNothing(builtinMesh(kDefaultBuiltinMesh), glm::mat4(1.0f), light, true, 5000);
}

TEST(LightFaceCulling, AMirroringModelMatrixKeepsEveryMap) {
  expectCullingChangesNothing(builtinMesh(kDefaultBuiltinMesh), glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)),
                              Light{}, true, 5000);
}

TEST(LightFaceCulling, ALightInsideAClosedMeshMeetsItsInnerFaces) {
  Light light;
  light.position = glm::vec3(0.1f, 0.2f, 0.5f);  // inside the cube [-1, 1]^3
  expectCullingChangesNothing(builtinMesh("cube"), glm::mat4(1.0f), light, false, kMapSize * kMapSize / 2);
}
