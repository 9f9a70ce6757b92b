// The transmission gather's skip (glow_rings_shared in shaders/lighting.frag.glsl): a 2 x 2 quad
// leaves out its ring taps where they can add at most GLOW_NEGLIGIBLE of the light the stone
// receives where the light entered, E / pi. Rendered with the skip and without it (the shader's
// threshold line replaced by -1, through a shader folder of the test's own), the linear pictures
// may differ by that much at most: GLOW_NEGLIGIBLE E / pi per pixel (the subsurface blur and the
// post pass's upsample average the lighting pass's light, the albedo is below 1), plus two
// half-float roundings of the pixel (the lighting and blur targets store half floats). Controls:
// the skip does fire in this scene (its quads marked), and a threshold too large by far (1: every
// quad skips) breaks the bound, so the measure sees a skip that cuts light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "gl_support.h"
#include "principled_stone.h"
#include "marble/gl/shader_library.h"
#include "marble/mesh/mesh.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
constexpr float kNegligible = 1.0f / 16384.0f;  // GLOW_NEGLIGIBLE in shaders/lighting.frag.glsl
const std::string kThresholdLine = "const float GLOW_NEGLIGIBLE = 1.0 / 16384.0;";
const std::string kSkipLine = "if (rings == 0) return vec3(0.0);";

// The built-in sphere (2 units across) at 30 mm per unit, lit from behind and a little above,
// in the default stone (sigma_t 2.2-3.0 per mm, albedo 0.999): chords from 0 at the rims to about
// 60 mm in the middle, so quads that drop all rings (chords of about 46 mm and more: T(23 mm)
// < 2^-14) or the outer ones lie next to quads whose rings carry light.
Scene sphereScene() {
  Scene s = backLitScene("test:sphere", 30.0f, kSize);
  s.material = Material{};
  s.light.position = {0.3f, 0.4f, -1.0f};
  s.material.ior = 1.0f;  // no specular glints: the picture is the light through the stone
  s.material.roughness = 1.0f;
  return s;
}

// A shader folder whose lighting.frag.glsl is the built-in one with `from` replaced by `to`;
// empty when the built-in one no longer has `from`.
std::filesystem::path changedLighting(const std::string& from, const std::string& to, const std::string& tag) {
  std::string text = embeddedShaders().at("lighting.frag.glsl");
  const auto at = text.find(from);
  if (at == std::string::npos) return {};
  text.replace(at, from.size(), to);
  const auto dir = std::filesystem::temp_directory_path() / ("marble-skip-" + tag + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "lighting.frag.glsl") << text;
  return dir;
}

ImageRGBF renderWith(const std::filesystem::path& dir) {
  Renderer renderer{ShaderLibrary(dir.string())};  // empty: the built-in shaders
  renderer.setMesh(builtinMesh("sphere"));
  renderImage(renderer, sphereScene());
  ImageRGBF img = renderer.readHdr();
  if (!dir.empty()) std::filesystem::remove_all(dir);
  return img;
}

ImageRGBF renderWithThreshold(const std::string& value, const std::string& tag) {
  const auto dir = changedLighting(kThresholdLine, "const float GLOW_NEGLIGIBLE = " + value + ";", tag);
  EXPECT_FALSE(dir.empty()) << "lighting.frag.glsl no longer has the line: " << kThresholdLine;
  return renderWith(dir);
}

struct Excess {
  int pixels = 0;      // channels beyond the bound
  float worst = 0.0f;  // the largest |difference| / bound
};

// Channels of `a` and `b` further apart than `allowed` (absolute) + two half-float steps.
Excess beyond(const ImageRGBF& a, const ImageRGBF& b, float allowed) {
  Excess e;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const float v = std::max(std::abs(a.pixels[i]), std::abs(b.pixels[i]));
    const float bound = allowed + 2.0f * v / 1024.0f;
    const float d = std::abs(a.pixels[i] - b.pixels[i]);
    e.pixels += d > bound;
    e.worst = std::max(e.worst, d / bound);
  }
  return e;
}

// E / pi: the directional light's irradiance (colour x intensity; no falloff) over pi.
float lightOverPi(const Scene& s) {
  return std::max({s.light.color.r, s.light.color.g, s.light.color.b}) * s.light.intensity / 3.14159265f;
}

struct TransmissionSkip : ::testing::Test {
  HeadlessContext& context = glContext();
};

}  // namespace

TEST_F(TransmissionSkip, DiffersFromTheFullGatherByLessThanItsBound) {
  const ImageRGBF skipped = renderWith({});
  const ImageRGBF full = renderWithThreshold("-1.0", "full");
  ASSERT_EQ(skipped.pixels.size(), full.pixels.size());
  const Excess e = beyond(skipped, full, kNegligible * lightOverPi(sphereScene()));
  EXPECT_EQ(e.pixels, 0) << "worst " << e.worst << " of the bound";
  std::cout << "[          ] skip against the full gather: worst " << e.worst << " of the bound\n";
}

// Not vacuous: the skip's branch is taken in this scene (its quads' rings set to 1 change the
// picture), and it is not taken everywhere the gather runs (the negative control below differs).
TEST_F(TransmissionSkip, SkipsSomeQuadsHere) {
  const ImageRGBF skipped = renderWith({});
  const auto dir = changedLighting(kSkipLine, "if (rings == 0) return vec3(1.0);", "marked");
  ASSERT_FALSE(dir.empty()) << "lighting.frag.glsl no longer has the line: " << kSkipLine;
  const ImageRGBF marked = renderWith(dir);
  const Excess e = beyond(skipped, marked, 0.01f);
  EXPECT_GT(e.pixels, 100) << "no quad of the sphere's thick middle took the skip (worst " << e.worst << ")";
}

// The negative control: a threshold of 1 skips every quad's rings (their sum is below 1 unless
// the chord is near its 2 mm floor), which takes visible light from the sphere's middle chords;
// the measure must see that beyond the bound.
TEST_F(TransmissionSkip, ControlTooLargeAThresholdBreaksTheBound) {
  const ImageRGBF tooLarge = renderWithThreshold("1.0", "too-large");
  const ImageRGBF full = renderWithThreshold("-1.0", "full");
  const Excess e = beyond(tooLarge, full, kNegligible * lightOverPi(sphereScene()));
  EXPECT_GT(e.pixels, 100) << "the measure missed a skip that cuts the rings' light (worst " << e.worst << ")";
  std::cout << "[          ] threshold 1: " << e.pixels << " channels beyond the bound, worst " << e.worst << "\n";
}
