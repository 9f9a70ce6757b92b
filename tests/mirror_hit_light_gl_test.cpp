// shaders/mirror_hit_light.glsl: the light a mirror ray's hit on screen sends, read from the
// half-resolution blurred light: the nearest blur texel, unless its view depth (alpha) lies farther
// from the hit's than one surface's tolerance; then of the 3 x 3 around it the one nearest the hit's
// depth: at a depth edge the nearest texel may lie on the part beside the hit,
// with other light (teapot-back's handle arm before its body, docs/quality.md, "Twenty-seventh
// session: the mirror image's light read on the hit's own surface"). Checked on the function itself,
// compiled into a compute shader over a small texture of our own.
// Negative control, checked by hand: mirror_hit_light returning the nearest texel's light (the code
// before the change), rebuilt: AtADepthEdgeTheHitsOwnSurfaceIsRead fails, OnOneSurfaceTheNearestTexelIsRead
// passes; the search without the tolerance (any nearer depth wins): OnOneSurfaceTheNearestTexelIsRead fails.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <array>
#include <string>
#include <vector>

#include "gl_support.h"
#include "marble/gl/checked_calls.h"
#include "marble/gl/handles.h"
#include "marble/gl/shader_library.h"

namespace marble {
namespace {

constexpr int kSize = 6;  // the blurred light's texels a side

const char* kComputeMain = R"(
layout(local_size_x = 1) in;
layout(binding = 0) uniform sampler2D u_blurred;
layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };  // texel x, y; hit depth; tolerance
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  results[i] = vec4(mirror_hit_light(u_blurred, ivec2(queries[i].xy), queries[i].z, queries[i].w), 0.0);
}
)";

struct Query {
  int x, y;
  float depth, sameSurface;
};

class MirrorHitLightGlTest : public test::ComputeProgramTest {
protected:
  void SetUp() override { compileProgram(embeddedShaders().at("nearest_texel.glsl") + embeddedShaders().at("mirror_hit_light.glsl") + kComputeMain); }

  // The red channel of the light read for each query over `texels` (rgb = light, a = view depth).
  std::vector<float> read(const std::vector<std::array<float, 4>>& texels, const std::vector<Query>& queries) {
    gl::Texture blurred = gl::makeTexture2D(GL_RGBA32F, kSize, kSize, GL_NEAREST);
    glTextureSubImage2D(blurred.id(), 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, texels.data());
    std::vector<float> in;
    for (const Query& q : queries) in.insert(in.end(), {static_cast<float>(q.x), static_cast<float>(q.y), q.depth, q.sameSurface});
    glBindTextureUnit(0, blurred.id());
    const std::vector<float> result = test::runPerVec4(program_, in);
    std::vector<float> r;
    for (size_t i = 0; i < queries.size(); ++i) r.push_back(result[4 * i]);
    return r;
  }

};

// A thin lit part (column 2, depth 2, light 1) before a dark body (the other columns, depth 3,
// light 0.05), one surface's tolerance 0.1. A hit on the part whose nearest texel is the body's
// (column 1 or 3) reads the part's light; a hit on the body beside the part reads the body's.
TEST_F(MirrorHitLightGlTest, AtADepthEdgeTheHitsOwnSurfaceIsRead) {
  std::vector<std::array<float, 4>> texels;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      texels.push_back(x == 2 ? std::array<float, 4>{1.0f, 1.0f, 1.0f, 2.0f} : std::array<float, 4>{0.05f, 0.05f, 0.05f, 3.0f});
  const auto got = read(texels, {{1, 3, 2.0f, 0.1f}, {3, 3, 2.05f, 0.1f}, {2, 3, 2.9f, 0.1f}, {0, 0, 3.0f, 0.1f}});
  EXPECT_EQ(got[0], 1.0f);
  EXPECT_EQ(got[1], 1.0f);
  EXPECT_EQ(got[2], 0.05f);
  EXPECT_EQ(got[3], 0.05f);
}

// On one slanted surface (depth rising 0.02 a column, light by column) the nearest texel's light
// where its depth lies within the tolerance of the hit's, even where a neighbour's lies nearer.
TEST_F(MirrorHitLightGlTest, OnOneSurfaceTheNearestTexelIsRead) {
  std::vector<std::array<float, 4>> texels;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) texels.push_back({0.1f * static_cast<float>(x), 0.0f, 0.0f, 2.0f + 0.02f * static_cast<float>(x)});
  const auto got = read(texels, {{0, 0, 2.015f, 0.05f}, {3, 2, 2.075f, 0.05f}, {5, 5, 2.09f, 0.05f}});
  EXPECT_FLOAT_EQ(got[0], 0.0f);
  EXPECT_FLOAT_EQ(got[1], 0.3f);
  EXPECT_FLOAT_EQ(got[2], 0.5f);
}

}  // namespace
}  // namespace marble
