// The transmission gather's rings left out where they add nothing (glow_rings_shared in
// shaders/lighting.frag.glsl): a 2 x 2 quad reads only the rings whose inner radius a_i keeps
// the optical distance a_i sigma_t below the slab table's end (tau_max, past which
// slab_transport is exactly 0), so leaving the others out must change no bit. Rendered with the
// shader as built and with every ring read (its ring count replaced, through a shader folder of
// the test's own), the linear pictures must be equal. Controls: rings are left out in this scene
// (its quads marked), and a cut 8x too early (a_i sigma_t against tau_max / 8) changes the
// picture, so the comparison sees a cut that drops light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
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
const std::string kCountLine = "int rings = most.x * mm <= GLOW_FROM_MM ? 0 : int(most.y + 0.5);";
const std::string kTauLine = "float tau_inner = 0.5 * S * mm *";
const std::string kResultLine = "return ok ? sum * (4.0 / taken) : vec3(0.0);";

// The built-in sphere (2 units across) at 30 mm per unit, lit from behind and a little above,
// in the default stone (sigma_t 2.19-3.01 per mm): chords from 0 at the rims to about 60 mm in
// the middle, so quads that read no ring (S from 58 mm), one or two lie next to quads that read
// all three.
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

ImageRGBF renderChanged(const std::string& from, const std::string& to, const std::string& tag) {
  const auto dir = changedLighting(from, to, tag);
  EXPECT_FALSE(dir.empty()) << "lighting.frag.glsl no longer has the line: " << from;
  return renderWith(dir);
}

ImageRGBF renderAllRings() {
  return renderChanged(kCountLine, "int rings = most.x * mm <= GLOW_FROM_MM ? 0 : GLOW_RINGS;", "all");
}

// Channels of `a` and `b` more than `allowed` apart.
int differing(const ImageRGBF& a, const ImageRGBF& b, float allowed) {
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += std::abs(a.pixels[i] - b.pixels[i]) > allowed;
  return n;
}

struct TransmissionSkip : ::testing::Test {
  HeadlessContext& context = glContext();
};

}  // namespace

TEST_F(TransmissionSkip, LeavingOutTheRingsThatAddNothingChangesNoBit) {
  const ImageRGBF cut = renderWith({});
  const ImageRGBF all = renderAllRings();
  ASSERT_EQ(cut.pixels.size(), all.pixels.size());
  EXPECT_EQ(differing(cut, all, 0.0f), 0);
}

// Not vacuous: quads whose chords pass GLOW_FROM_MM read no ring in this scene (marked with
// rings of 1, they change the picture).
TEST_F(TransmissionSkip, SomeQuadsReadNoRingHere) {
  const ImageRGBF cut = renderWith({});
  const ImageRGBF marked = renderChanged(
      kResultLine, "return ok ? sum * (4.0 / taken) + vec3(rings == 0 && most.x * mm > GLOW_FROM_MM ? 1.0 : 0.0) : vec3(0.0);",
      "marked");
  EXPECT_GT(differing(cut, marked, 0.01f), 100) << "no quad of the sphere's thick middle left its rings out";
}

// The negative control: rings cut where a_i sigma_t passes tau_max / 8 still carry light; the
// comparison must see that.
TEST_F(TransmissionSkip, ControlCutTooEarlyChangesThePicture) {
  const ImageRGBF early = renderChanged(kTauLine, "float tau_inner = 4.0 * S * mm *", "early");
  const ImageRGBF all = renderAllRings();
  const int n = differing(early, all, 0.0f);
  EXPECT_GT(n, 100) << "the comparison missed a cut that drops the rings' light";
  std::cout << "[          ] cut 8x too early: " << n << " channels differ\n";
}
