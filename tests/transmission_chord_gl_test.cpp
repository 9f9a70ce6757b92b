// shaders/transmission_chord.glsl: the transmission's chord read from the light's map. Across an
// edge of the map (a part's outline seen from the light, with another surface nearer the light
// beside it: the teapot's lid rim below its dome) the four texels' chords are averaged by the
// light each lets through, exp(-sigma_tr s), not by their entries: the mean of the entries is an
// entry on neither surface, whose chord lets nothing through (teapot-back's rim dark beside the
// knob's shadow, docs/quality.md, "Twenty-seventh session: the chord's read across the light map's
// edge"). A texel whose chord is under half a texel (an entry at or behind the point) is left out.
// Checked here on the function itself, compiled into a compute shader with a light travelling along
// +z and a small map of our own: at an edge, on one surface, and beside a texel with no chord.
// Negative control, checked by hand: transmission_chord returning the bilinear read of the entries
// (the code before the change), rebuilt: TheEdgesTwoSurfacesEachLetTheirOwnLightThrough and
// AnEntryBehindThePointIsLeftOut fail, OnOneSurfaceTheChordIsTheBilinearOne passes.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gl_support.h"
#include "light_along_z.h"
#include "marble/gl/checked_calls.h"
#include "marble/gl/handles.h"
#include "marble/gl/shader_library.h"

namespace marble {
namespace {

constexpr int kMap = 8;              // the map's texels a side, spanning x, y in [-1, 1]
constexpr float kTexel = 2.0f / kMap;  // 0.25 scene units
constexpr float kDecay = 8.0f;        // sigma_tr per scene unit
constexpr float kExitZ = 1.0f;        // the points read, at distance 1 along the light

// The light travels along +z (light_along_z.h); each query point's (chord, cosine).
const std::string kComputeMain = test::perVec4Main("  results[i] = vec4(transmission_chord(q.xyz, q.xyz), 0.0, 0.0);");

// A map whose column x holds entry(x) and cosine(x) (every row the same).
struct Column {
  float entry, cosine;
};

class TransmissionChordGlTest : public test::ComputeProgramTest {
protected:
  void SetUp() override { compileProgram(test::kLightAlongZ + embeddedShaders().at("transmission_chord.glsl") + kComputeMain); }

  // (chord, cosine) at each x (y = 0, z = kExitZ) over the map of columns.
  std::vector<std::array<float, 2>> chords(const std::array<Column, kMap>& columns, const std::vector<float>& xs) {
    std::vector<float> texels(2 * kMap * kMap);
    for (int y = 0; y < kMap; ++y)
      for (int x = 0; x < kMap; ++x) {
        texels[2 * (y * kMap + x)] = columns[static_cast<size_t>(x)].entry;
        texels[2 * (y * kMap + x) + 1] = columns[static_cast<size_t>(x)].cosine;
      }
    gl::Texture map = gl::makeTexture2D(GL_RG32F, kMap, kMap, GL_NEAREST);
    glTextureSubImage2D(map.id(), 0, 0, 0, kMap, kMap, GL_RG, GL_FLOAT, texels.data());
    std::vector<float> points;
    for (float x : xs) points.insert(points.end(), {x, 0.0f, kExitZ, 0.0f});
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    glProgramUniformMatrix4fv(program_, glGetUniformLocation(program_, "u_light_view_proj"), 1, GL_FALSE, identity);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_light_texel_world"), kTexel);
    glProgramUniform2f(program_, glGetUniformLocation(program_, "u_light_near_far"), 0.0f, 10.0f);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_chord_decay"), kDecay);
    glBindTextureUnit(0, map.id());
    const std::vector<float> result = test::runPerVec4(program_, points);
    std::vector<std::array<float, 2>> r;
    for (size_t i = 0; i < xs.size(); ++i) r.push_back({result[4 * i], result[4 * i + 1]});
    return r;
  }

};

// The lid rim's case: left of x = 0 the light entered a surface 1 unit before the points (the
// dome), right of it 0.2 unit before (the lip; over half a texel, so kept whole). At x = 0 the read weighs the texels either side
// half and half; a quarter texel further each way, 3/4 and 1/4. The light let through,
// exp(-sigma_tr s), must be the weights' mean of each texel's, and the cosine that of the texels
// weighted by the light each lets through (the bilinear mean of the entries: exp(-4.8) = 0.008
// at x = 0 where half the footprint lets exp(-1.6) = 0.20 through).
TEST_F(TransmissionChordGlTest, TheEdgesTwoSurfacesEachLetTheirOwnLightThrough) {
  std::array<Column, kMap> columns;
  for (int x = 0; x < kMap; ++x) columns[static_cast<size_t>(x)] = x < kMap / 2 ? Column{0.0f, 0.3f} : Column{0.8f, 0.9f};
  const std::vector<float> xs = {-0.25f * kTexel, 0.0f, 0.25f * kTexel};
  const auto got = chords(columns, xs);
  for (size_t i = 0; i < xs.size(); ++i) {
    const float right = 0.5f + xs[i] / kTexel;  // the bilinear weight of the lip's texels
    const double farT = std::exp(-kDecay * 1.0), nearT = std::exp(-kDecay * 0.2);
    const double through = (1.0 - right) * farT + right * nearT;
    const double cosine = ((1.0 - right) * farT * 0.3 + right * nearT * 0.9) / through;
    EXPECT_NEAR(std::exp(-kDecay * got[i][0]) / through, 1.0, 1e-4) << "x " << xs[i] << " chord " << got[i][0];
    EXPECT_NEAR(got[i][1], cosine, 1e-4) << "x " << xs[i];
  }
}

// On one surface (an entry plane slanted so that the entry moves by 0.02 units a texel) the
// chord is the bilinear one, d - the entries' mean, less sigma_tr var / 2: under 1e-3 here.
TEST_F(TransmissionChordGlTest, OnOneSurfaceTheChordIsTheBilinearOne) {
  std::array<Column, kMap> columns;
  for (int x = 0; x < kMap; ++x) columns[static_cast<size_t>(x)] = {0.5f + 0.02f * static_cast<float>(x), 0.7f};
  const std::vector<float> xs = {-0.3f, -0.1f, 0.05f, 0.2f, 0.4f};
  const auto got = chords(columns, xs);
  for (size_t i = 0; i < xs.size(); ++i) {
    const float t = (xs[i] + 1.0f) / kTexel - 0.5f;  // the read's position in texels
    const float entry = 0.5f + 0.02f * t;
    EXPECT_NEAR(got[i][0], kExitZ - entry, 1e-3) << "x " << xs[i];
    EXPECT_NEAR(got[i][1], 0.7f, 1e-5) << "x " << xs[i];
  }
}

// An entry at or behind the point (the map saw the point's own side: an open wall, a grazing
// face) tells nothing of the light reaching it: beside it the other texels' chord, and where all
// four are such, the zero chord of the bilinear read (its entry_cosine takes the exit's cosine).
TEST_F(TransmissionChordGlTest, AnEntryBehindThePointIsLeftOut) {
  std::array<Column, kMap> columns;
  for (int x = 0; x < kMap; ++x) columns[static_cast<size_t>(x)] = x < kMap / 2 ? Column{1.5f, 0.2f} : Column{0.8f, 0.9f};
  const auto got = chords(columns, {-0.25f * kTexel, 0.0f, 0.25f * kTexel, -0.5f});
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(got[static_cast<size_t>(i)][0], 0.2f, 1e-4) << i;
    EXPECT_NEAR(got[static_cast<size_t>(i)][1], 0.9f, 1e-5) << i;
  }
  EXPECT_EQ(got[3][0], 0.0f);
}

}  // namespace
}  // namespace marble
