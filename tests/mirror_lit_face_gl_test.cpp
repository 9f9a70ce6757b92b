// shaders/mirror_lit_face.glsl: where the screen-space mirror march takes a visible face for its hit
// but the ray has passed behind it into a face the camera cannot see, lit by the light (teapot-back's
// shoulder and body edge mirroring the spout's and the handle arm's sides toward the body,
// docs/quality.md, "Twenty-eighth session: ... the lit face behind the mirror hit"). Checked on the
// functions themselves, compiled into a compute shader: the test that tells the hidden lit face from
// the visible one by the ray point's two distances (behind the visible face, from the light's entry),
// and its two halves, each a test of its own distance; and the face's light spread by the walk
// (session 29).
// Negative controls, checked by hand: mirror_behind_visible_face returning false (main's behaviour:
// the visible face kept for every hit), rebuilt: both tests fail; lit_face_spread returning the
// face's own coupling (main's behaviour before session 29), rebuilt: SpreadsTheRingsLightIntoTheFace
// fails (0.4 for 0.65).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_support.h"
#include "marble/gl/shader_library.h"

namespace marble {
namespace {

// Query: gap, below, the light map's texel.
const char* kDecide = R"(
  results[i] = vec4(mirror_meets_lit_face(q.x, q.y, q.z) ? 1.0 : 0.0,
                    mirror_behind_visible_face(q.x) && mirror_at_light_entry(q.y, q.z) ? 1.0 : 0.0, 0.0, 0.0);
)";

// The face's light spread by the walk (lit_face_spread): its own coupling and a ring of taps, each
// query's taps alike. Query: own coupling, the taps' coupling, their entry offset, the ring's radius.
const char* kSpread = R"(
  vec2 sum = vec2(0.0);
  for (int k = 0; k < LIT_FACE_RING_TAPS; ++k) sum += lit_face_ring_tap(1.0 + q.z, q.y, 1.0, q.w);
  results[i] = vec4(lit_face_spread(q.x, sum), 0.0, 0.0, 0.0);
)";

// mirror_lit_face.glsl's functions, run once per query by the compute shader main `body`.
class MirrorLitFaceGlTest : public test::ComputeProgramTest {
protected:
  std::vector<float> run(const char* body, const std::vector<float>& in) {
    compileProgram(embeddedShaders().at("mirror_lit_face.glsl") + test::perVec4Main(body));
    if (program_ == 0) return {};
    return test::runPerVec4(program_, in);
  }
};

// Behind the visible face by more than the bisection leaves and at the light's entry surface: the lit
// face hidden there (teapot-back's mirror line: gap 0.03-0.06, below -0.01 ... 0.05). On the visible
// face (gap <= 0.01) or inside a part the light does not reach directly (below 0.1-0.2): not.
TEST_F(MirrorLitFaceGlTest, TellsTheLitFaceBehindFromTheVisibleFace) {
  const float texel = 0.00338f;  // teapot-back's light map texel, scene units
  struct Case { float gap, below; bool lit; };
  const std::vector<Case> cases = {{0.045f, 0.015f, true},  {0.056f, -0.012f, true}, {0.061f, -0.009f, true},
                                   {0.004f, 0.010f, false}, {0.010f, 0.0f, false},   {0.045f, 0.126f, false},
                                   {0.045f, -0.05f, false}};
  std::vector<float> in;
  for (const Case& c : cases) in.insert(in.end(), {c.gap, c.below, texel, 1.0f});
  const std::vector<float> out = run(kDecide, in);
  for (size_t i = 0; i < cases.size(); ++i)
    EXPECT_EQ(out[4 * i], cases[i].lit ? 1.0f : 0.0f) << "gap " << cases[i].gap << " below " << cases[i].below;
}

// The two halves (behind the visible face; at the light's entry) together decide as the whole test.
TEST_F(MirrorLitFaceGlTest, HalvesDecideAsTheWhole) {
  const float texel = 0.00338f;
  std::vector<float> in;
  for (float gap = 0.0f; gap < 0.08f; gap += 0.005f)
    for (float below = -0.06f; below < 0.2f; below += 0.01f) in.insert(in.end(), {gap, below, texel, 1.0f});
  const std::vector<float> out = run(kDecide, in);
  int lit = 0;
  for (size_t i = 0; i < in.size() / 4; ++i) {
    EXPECT_EQ(out[4 * i + 1], out[4 * i]) << "gap " << in[4 * i] << " below " << in[4 * i + 1];
    lit += out[4 * i] > 0.5f ? 1 : 0;
  }
  EXPECT_GT(lit, 0);
}

// A face lit at a grazing cosine beside its part's back lit head-on (teapot-back's hidden faces: own
// coupling about 0.4, the ring 0.9): the walk brings half its light from the ring, so the face
// reads the mean of the two halves, not its own (what it read before session 29). A face lit alike
// all round keeps its own light; taps on another part (their entry more than two ring radii away
// along the light) are left out, and with none left the face keeps its own.
TEST_F(MirrorLitFaceGlTest, SpreadsTheRingsLightIntoTheFace) {
  const float ring = 0.0206f;  // the issue's stone at 100 mm per unit, scene units
  const std::vector<float> out = run(kSpread, {0.4f, 0.9f, 0.005f, ring,     //
                                      0.6f, 0.6f, -0.01f, ring,     //
                                      0.4f, 0.9f, 3.0f * ring, ring,  //
                                      0.4f, 0.9f, -3.0f * ring, ring});
  EXPECT_NEAR(out[0], 0.65f, 1e-5f) << "a grazing-lit face beside a head-on-lit back";
  EXPECT_NEAR(out[4], 0.6f, 1e-5f) << "lit alike all round";
  EXPECT_NEAR(out[8], 0.4f, 1e-5f) << "the ring on a part behind";
  EXPECT_NEAR(out[12], 0.4f, 1e-5f) << "the ring on a part in front";
}

}  // namespace
}  // namespace marble
