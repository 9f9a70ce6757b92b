// shaders/mirror_march_phase.glsl: where along its geometric steps each lighting texel's screen-space
// mirror march starts. With one fixed start the rays of a band of texels step over a thin part
// together (teapot-back's handle arm mirrored in its body, docs/quality.md, "Twenty-eighth session:
// ... the screen march's fixed phase"); the start is stratified over the texels instead, a 4 x 4 ordered
// dither. Checked on the function itself, compiled into a compute shader: every aligned 4 x 4 block
// of texels holds the 16 offsets (k + 0.5) / 16 once, and every aligned 2 x 2 block four of them a
// quarter of a step apart (the texels one pixel of the 200^2 measurement covers at 800^2).
// Negative control, checked by hand: mirror_march_phase returning 0 (the fixed start before the
// change) or one phase for all texels, rebuilt: both tests fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "gl_support.h"
#include "marble/gl/shader_library.h"

namespace marble {
namespace {

const char* kComputeMain = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };  // texel x, y
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  results[i] = vec4(mirror_march_phase(ivec2(queries[i].xy)), 0.0, 0.0, 0.0);
}
)";

class MirrorMarchPhaseGlTest : public test::ComputeProgramTest {
protected:
  void SetUp() override { compileProgram(embeddedShaders().at("mirror_march_phase.glsl") + kComputeMain); }

  // The phases of the size x size texels from (x0, y0), row by row.
  std::vector<float> phases(int x0, int y0, int size) {
    std::vector<float> in;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) in.insert(in.end(), {static_cast<float>(x0 + x), static_cast<float>(y0 + y), 0.0f, 0.0f});
    const std::vector<float> result = test::runPerVec4(program_, in);
    std::vector<float> r;
    for (size_t i = 0; i < in.size() / 4; ++i) r.push_back(result[4 * i]);
    return r;
  }
};

// Each aligned 4 x 4 block (here at the origin and one far out, as in an 800^2 frame) holds every
// offset (k + 0.5) / 16 once: the march's points are spread evenly over a step.
TEST_F(MirrorMarchPhaseGlTest, EveryFourByFourBlockHoldsEachOffsetOnce) {
  for (const auto& origin : {std::pair<int, int>{0, 0}, std::pair<int, int>{396, 212}}) {
    std::vector<float> p = phases(origin.first, origin.second, 4);
    std::sort(p.begin(), p.end());
    for (int k = 0; k < 16; ++k) EXPECT_EQ(p[k], (static_cast<float>(k) + 0.5f) / 16.0f) << "block at " << origin.first << ", " << origin.second;
  }
}

// Each aligned 2 x 2 block holds four offsets a quarter of a step apart.
TEST_F(MirrorMarchPhaseGlTest, EveryTwoByTwoBlockSpansTheStep) {
  const std::vector<float> p = phases(0, 0, 8);
  for (int by = 0; by < 8; by += 2)
    for (int bx = 0; bx < 8; bx += 2) {
      std::vector<float> q = {p[by * 8 + bx], p[by * 8 + bx + 1], p[(by + 1) * 8 + bx], p[(by + 1) * 8 + bx + 1]};
      std::sort(q.begin(), q.end());
      for (int i = 1; i < 4; ++i) EXPECT_EQ(q[i] - q[i - 1], 0.25f) << "block " << bx << ", " << by;
    }
}

}  // namespace
}  // namespace marble
