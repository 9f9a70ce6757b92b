// The triangles the geometry pass drops before GL (render/screen_cull.h) are never ones GL draws:
// (1) tiny triangles of every sense around pixel centres, where llvmpipe's snapping of the corners
// to 1/256 pixel turns many: each that GL draws with back faces culled (counted per primitive in a
// storage buffer) is among those trianglesGlMayDraw keeps; control: with no slack it drops some
// that GL draws. (2) The renderer's frame of the dense sculpture, from outside, and mirrored, with
// and without the cull before GL: equal bit for bit.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "dense_mesh.h"
#include "gl_support.h"
#include "principled_stone.h"
#include "marble/gl/software_rasterizer.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/screen_cull.h"

using namespace marble;
using namespace marble::test;

namespace {

// Counts each primitive's fragments (gl_PrimitiveID: the triangle's place in the draw, culled
// ones included) in the storage buffer at binding 0.
GLuint countingProgram() {
  const GLuint vs = compileShaderStage(GL_VERTEX_SHADER, R"(#version 450 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); })");
  const GLuint fs = compileShaderStage(GL_FRAGMENT_SHADER, R"(#version 450 core
layout(std430, binding = 0) buffer Counts { uint counts[]; };
out vec4 o_color;
void main() { atomicAdd(counts[gl_PrimitiveID], 1u); o_color = vec4(1.0); })");
  return linkTestProgram({vs, fs});
}

// How many fragments GL draws of each triangle, back faces culled, into a size x size viewport.
std::vector<uint32_t> fragmentsPerTriangle(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                                           const glm::mat4& mvp, int size) {
  glContext();
  OffscreenTarget target(size, size);
  const GLuint program = countingProgram();
  gl::Buffer vertices = gl::Buffer::create(), elements = gl::Buffer::create(), counts = gl::Buffer::create();
  gl::VertexArray vao = gl::VertexArray::create();
  glNamedBufferStorage(vertices.id(), static_cast<GLsizeiptr>(positions.size() * sizeof(glm::vec3)), positions.data(), 0);
  glNamedBufferStorage(elements.id(), static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)), indices.data(), 0);
  const std::vector<uint32_t> zero(indices.size() / 3, 0u);
  glNamedBufferStorage(counts.id(), static_cast<GLsizeiptr>(zero.size() * sizeof(uint32_t)), zero.data(), 0);
  glVertexArrayVertexBuffer(vao.id(), 0, vertices.id(), 0, sizeof(glm::vec3));
  glVertexArrayElementBuffer(vao.id(), elements.id());
  glEnableVertexArrayAttrib(vao.id(), 0);
  glVertexArrayAttribFormat(vao.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao.id(), 0, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo());
  glViewport(0, 0, size, size);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glUseProgram(program);
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "u_mvp"), 1, GL_FALSE, &mvp[0][0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counts.id());
  glBindVertexArray(vao.id());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr);
  glDisable(GL_CULL_FACE);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<uint32_t> out(zero.size());
  glGetNamedBufferSubData(counts.id(), 0, static_cast<GLsizeiptr>(out.size() * sizeof(uint32_t)), out.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  test::deleteTestProgram(program);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

// Triangles GL draws (any fragment) that trianglesGlMayDraw drops.
size_t drawnButDropped(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                       const std::vector<uint32_t>& fragments, const glm::mat4& mvp, int size, double slack) {
  Mesh mesh;
  mesh.positions = positions;
  mesh.indices = indices;
  std::vector<uint32_t> kept(indices.size());
  std::vector<float> scratch;
  kept.resize(3 * trianglesGlMayDraw(ScreenCullMesh(mesh), mvp, size, size, CulledSense::Clockwise, kept.data(), scratch,
                                     slack));
  // The kept list is in the draw's order: walk both.
  size_t k = 0, missing = 0;
  for (size_t t = 0; t < fragments.size(); ++t) {
    const bool isKept = k + 2 < kept.size() && kept[k] == indices[3 * t] && kept[k + 1] == indices[3 * t + 1] &&
                        kept[k + 2] == indices[3 * t + 2];
    if (isKept) k += 3;
    missing += fragments[t] > 0 && !isKept;
  }
  return missing;
}

TEST(ScreenCull, NoTriangleGlDrawsIsDropped) {
  // Eight triangles around each pixel centre of a 64^2 viewport, their corners within 1/100 pixel
  // of it (every corner its own vertex, so the indices name each triangle once).
  const int size = 64;
  const glm::mat4 mvp = glm::ortho(0.0f, float(size), 0.0f, float(size), -1.0f, 1.0f);  // one unit a pixel
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> offset(-0.01f, 0.01f);
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int k = 0; k < 8 * 3; ++k) {
        indices.push_back(static_cast<uint32_t>(positions.size()));
        positions.emplace_back(x + 0.5f + offset(rng), y + 0.5f + offset(rng), 0.0f);
      }
  const std::vector<uint32_t> fragments = fragmentsPerTriangle(positions, indices, mvp, size);
  size_t drawn = 0;
  for (uint32_t f : fragments) drawn += f > 0;
  EXPECT_GT(drawn, 1000u) << "the test must see GL draw tiny triangles";
  EXPECT_EQ(drawnButDropped(positions, indices, fragments, mvp, size, kScreenCullSlackPixels), 0u);
  // Control: the sense computed here with no slack disagrees with GL's snapped one for some.
  EXPECT_GT(drawnButDropped(positions, indices, fragments, mvp, size, 0.0), 0u);
}

void expectTheSameFrame(const glm::mat4& model) {
  glContext();
  // Elsewhere the mesh prepares no cull before GL, and both renderers would be GL's alone.
  if (!gl::rasterizesInSoftware()) GTEST_SKIP() << "the cull before GL runs only on a software rasterizer";
  Scene s;
  s.render.width = 203;
  s.render.height = 151;
  s.render.mode = RenderMode::Marble;
  s.material = test::principledStone(glm::vec3(0.8f));
  const Mesh mesh = subdividedSmoothed(builtinMesh(kDefaultBuiltinMesh), 1);
  Renderer onCpu, glOnly;
  glOnly.setGeometryCullsOnCpu(false);
  onCpu.setMesh(mesh);
  glOnly.setMesh(mesh);
  const FramePairDifference d = compareFrames(onCpu, glOnly, s, model);
  EXPECT_GT(d.litPixels, 1000u) << "the view must see the mesh";
  EXPECT_EQ(d.differingValues, 0u);
}

}  // namespace

TEST(ScreenCull, AMeshCullsOnTheCpuExactlyWhereGlRasterizesInSoftware) {
  glContext();
  const GpuMesh mesh(builtinMesh(kDefaultBuiltinMesh));
  EXPECT_EQ(mesh.cullsOnCpu(), gl::rasterizesInSoftware());
  EXPECT_EQ(mesh.screenCullMesh().indices.size(), mesh.cullsOnCpu() ? 3 * mesh.triangleCount() : 0u);
}

TEST(ScreenCull, TheSculptureIsTheFrameGlCullsAlone) { expectTheSameFrame(glm::mat4(1.0f)); }

TEST(ScreenCull, AMirroredSculptureIsTheFrameGlCullsAlone) {
  expectTheSameFrame(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)));
}
