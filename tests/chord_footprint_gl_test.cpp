// shaders/chord_footprint.glsl: the transmission's chord at a rim beside a shadow edge. On a face
// turned from the light the chord's texels are read at the exit's own light ray, not two texels
// sideways along -N (the inward offset P_in = P - 2 texels N), which at teapot-back's lid rim
// crossed the knob's shadow edge; and below a short chord half the light comes from a ring of
// taps at the walk's radius across the light, so a shadow edge within the ring darkens the rim
// (docs/quality.md, "Thirtieth session: the rim's chord read at the exit's own light ray").
// Checked on the functions themselves, compiled into a compute shader with a light travelling
// along +z over a small map of our own: a shadow caster's entries left of x = 0 (a long chord),
// a thin rim's right of it (a short one).
// Negative controls, checked by hand (each rebuilt): chord_read_point stepping two texels sideways
// of the exit's ray, as P_in's read does, fails TheReadStaysOnTheExitsOwnLightRay (and the two
// tests after it); chord_footprint returning s (no footprint) fails only
// AShadowWithinTheWalksRingDarkensAShortChord; chord_own_ray_share returning 0 (P_in's read kept
// everywhere, main's behaviour) fails only TheOwnRaysReadOnlyWhereTheOffsetCrossedOntoANearerEntry.
// OnOneSurfaceTheFootprintKeepsTheChord passes in all three (it guards the footprint's neutrality).
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

constexpr int kMap = 16;               // the map's texels a side, spanning x, y in [-1, 1]
constexpr float kTexel = 2.0f / kMap;  // 0.125 scene units
constexpr float kDecay = 4.0f;         // sigma_tr per scene unit
constexpr float kRing = 0.3f;          // the footprint's ring, 2.4 texels
constexpr float kFrom = 0.5f;          // the footprint below 0.5 of chord, blended out by 1.0
constexpr float kShadowEntry = 0.1f;   // left of x = 0: the caster's entry, near the light
constexpr float kRimEntry = 0.55f;     // right of it: the rim's lit top
constexpr float kExitZ = 1.0f;         // the exits' distance along the light

// The light travels along +z (light_along_z.h), so L = -z.
const std::string kPreamble =
    std::string(test::kLightAlongZ) + "vec3 light_vector(vec3 p) { return vec3(0.0, 0.0, -1.0); }\n";

// Per exit (P, N): .x the chord read at chord_read_point, .y after chord_footprint, .z the chord
// read at P_in itself (main's read before the change), .w chord_own_ray_share of the two.
const char* kComputeMain = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
uniform float u_ring;
uniform float u_from;
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec3 P = points[2 * i].xyz, N = points[2 * i + 1].xyz;
  vec3 P_in = P - N * (2.0 * u_light_texel_world);
  vec3 L = light_vector(P);
  vec3 at = chord_read_point(P, L, dot(N, L));
  float s = transmission_chord(P_in, at).x, s_in = transmission_chord(P_in, P_in).x;
  results[i] = vec4(s, chord_footprint(at, light_distance_of(P_in), s, u_ring, u_from), s_in,
                    chord_own_ray_share(s_in, s));
}
)";

struct Exit {
  float x, y, nx, nz;  // on the plane z = kExitZ, normal (nx, 0, nz)
};

class ChordFootprintGlTest : public test::ComputeProgramTest {
protected:
  void SetUp() override {
    const auto& shaders = embeddedShaders();
    compileProgram(kPreamble + shaders.at("transmission_chord.glsl") + shaders.at("chord_footprint.glsl") + kComputeMain);
  }

  // The map: entryAt(x of the texel's centre) in every row; cosine 1.
  template <class Entry>
  std::vector<std::array<float, 4>> read(Entry entryAt, const std::vector<Exit>& exits) {
    std::vector<float> texels(2 * kMap * kMap);
    for (int y = 0; y < kMap; ++y)
      for (int x = 0; x < kMap; ++x) {
        texels[2 * (y * kMap + x)] = entryAt(-1.0f + (static_cast<float>(x) + 0.5f) * kTexel);
        texels[2 * (y * kMap + x) + 1] = 1.0f;
      }
    gl::Texture map = gl::makeTexture2D(GL_RG32F, kMap, kMap, GL_NEAREST);
    glTextureSubImage2D(map.id(), 0, 0, 0, kMap, kMap, GL_RG, GL_FLOAT, texels.data());
    std::vector<float> points;
    for (const Exit& e : exits) points.insert(points.end(), {e.x, e.y, kExitZ, 0.0f, e.nx, 0.0f, e.nz, 0.0f});
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    glProgramUniformMatrix4fv(program_, glGetUniformLocation(program_, "u_light_view_proj"), 1, GL_FALSE, identity);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_light_texel_world"), kTexel);
    glProgramUniform2f(program_, glGetUniformLocation(program_, "u_light_near_far"), 0.0f, 10.0f);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_chord_decay"), kDecay);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_ring"), kRing);
    glProgramUniform1f(program_, glGetUniformLocation(program_, "u_from"), kFrom);
    glBindTextureUnit(0, map.id());
    const std::vector<float> result = test::runPerVec4(program_, points);
    std::vector<std::array<float, 4>> r;
    for (size_t i = 0; i < exits.size(); ++i) r.push_back({result[4 * i], result[4 * i + 1], result[4 * i + 2], result[4 * i + 3]});
    return r;
  }
};

float rimBesideShadow(float x) { return x < 0.0f ? kShadowEntry : kRimEntry; }

// The rim's front face turned from the light (N = (0.8, 0, 0.6): N.L = -0.6) half a texel right of
// the shadow's edge: P_in lies 2 texels x 0.8 = 1.6 texels left, in the shadow, where main's read
// found the caster's chord; at the exit's own light ray the texels are the rim's. Both chords
// from P_in's distance to the light (1 - 2 texels x 0.6).
TEST_F(ChordFootprintGlTest, TheReadStaysOnTheExitsOwnLightRay) {
  const auto got = read(rimBesideShadow, {{0.5f * kTexel, 0.0f, 0.8f, 0.6f}});
  const float dIn = kExitZ - 2.0f * kTexel * 0.6f;
  EXPECT_NEAR(got[0][2], dIn - kShadowEntry, 1e-3) << "main's read: the shadow's texels";
  EXPECT_NEAR(got[0][0], dIn - kRimEntry, 1e-3) << "the exit's own ray: the rim's texels";
}

// A face turned straight from the light (N = +z: the read at P_in itself) 1.5 texels right of the
// edge, its chord 0.2 under kFrom: of the ring's four taps (+-x, +-y, 2.4 texels out) the one at
// -x lies in the shadow. Half the light is the straight chord's, half the taps' mean.
TEST_F(ChordFootprintGlTest, AShadowWithinTheWalksRingDarkensAShortChord) {
  const auto got = read(rimBesideShadow, {{1.5f * kTexel, 0.0f, 0.0f, 1.0f}});
  const double dIn = kExitZ - 2.0 * kTexel, rim = std::exp(-kDecay * (dIn - kRimEntry));
  const double shadow = std::exp(-kDecay * (dIn - kShadowEntry));
  const double through = 0.5 * rim + 0.5 * (3.0 * rim + shadow) / 4.0;
  EXPECT_NEAR(got[0][0], dIn - kRimEntry, 1e-4);
  EXPECT_NEAR(got[0][1], -std::log(through) / kDecay, 1e-4);
  EXPECT_GT(got[0][1], got[0][0] + 0.02f) << "darker than the straight chord";
}

// Where the ring's taps find the same entry as the read (one surface), the chord is kept; so is
// it where it is over twice kFrom (the gather's range), whatever the taps find.
TEST_F(ChordFootprintGlTest, OnOneSurfaceTheFootprintKeepsTheChord) {
  const auto flat = read([](float) { return kRimEntry; }, {{1.5f * kTexel, 0.0f, 0.0f, 1.0f}});
  EXPECT_NEAR(flat[0][1], flat[0][0], 1e-5);
  const auto longChord = read([](float x) { return x < 0.0f ? 2.0f : -0.5f; }, {{1.5f * kTexel, 0.0f, 0.0f, 1.0f}});
  EXPECT_NEAR(longChord[0][0], kExitZ - 2.0f * kTexel + 0.5f, 1e-4);
  EXPECT_EQ(longChord[0][1], longChord[0][0]);
}

// Where P_in's sideways step finds a nearer entry than the exit's own ray (the shadow's caster) the
// own ray's read is taken whole; where both find the same surface (here one entry plane across the
// light: the same chord), P_in's read is kept, as before the change.
TEST_F(ChordFootprintGlTest, TheOwnRaysReadOnlyWhereTheOffsetCrossedOntoANearerEntry) {
  const auto edge = read(rimBesideShadow, {{0.5f * kTexel, 0.0f, 0.8f, 0.6f}});
  EXPECT_EQ(edge[0][3], 1.0f);
  const auto flat = read([](float) { return kRimEntry; }, {{0.5f * kTexel, 0.0f, 0.8f, 0.6f}});
  EXPECT_NEAR(flat[0][0], flat[0][2], 1e-5);
  EXPECT_EQ(flat[0][3], 0.0f);
}

}  // namespace
}  // namespace marble
