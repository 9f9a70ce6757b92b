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
#include "slab_mesh.h"
#include "marble/gl/shader_library.h"
#include "marble/mesh/mesh.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kSize = 128;
const std::string kCountLine = "int rings = most.x * mm <= GLOW_FROM_MM ? 0 : int(most.y + 0.5);";
const std::string kTauLine = "float tau_inner = 0.5 * S * mm *";
const std::string kResultLine = "return ok ? sum * (4.0 / taken) : vec3(0.0);";
const std::string kAllRings = "int rings = most.x * mm <= GLOW_FROM_MM ? 0 : GLOW_RINGS;";

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

// A flat slab 8 mm thick (2 x 2 x 0.2 units at 40 mm per unit) in the default stone, lit from
// behind at 70 degrees: chords of 23 mm along the light, the entry plane 8 mm deep. The slanted
// gather's rings scale with that depth (glow_scale of slanted_depth), a third of glow_scale of the
// chord: the bound must use the taps' own S, or it leaves out rings that still carry light.
Scene slantedSlabScene() {
  Scene s = backLitScene("test:slab", 40.0f, kSize);
  s.material = Material{};
  const float theta = glm::radians(70.0f);
  s.light.position = {std::sin(theta), 0.0f, -std::cos(theta)};
  s.material.ior = 1.0f;
  s.material.roughness = 1.0f;
  return s;
}
Mesh slantedSlab() { return slabMesh(1.0f, 0.1f); }

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

ImageRGBF renderWith(const std::filesystem::path& dir, const Mesh& mesh = builtinMesh("sphere"),
                     const Scene& scene = sphereScene()) {
  Renderer renderer{ShaderLibrary(dir.string())};  // empty: the built-in shaders
  renderer.setMesh(mesh);
  renderImage(renderer, scene);
  ImageRGBF img = renderer.readHdr();
  if (!dir.empty()) std::filesystem::remove_all(dir);
  return img;
}

ImageRGBF renderChanged(const std::string& from, const std::string& to, const std::string& tag,
                        const Mesh& mesh = builtinMesh("sphere"), const Scene& scene = sphereScene()) {
  const auto dir = changedLighting(from, to, tag);
  EXPECT_FALSE(dir.empty()) << "lighting.frag.glsl no longer has the line: " << from;
  return renderWith(dir, mesh, scene);
}

ImageRGBF renderAllRings() { return renderChanged(kCountLine, kAllRings, "all"); }

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

// On a slanted flat entry the rings are placed on the entry's plane (slanted_frame) and scaled
// with its depth: leaving out the rings that add nothing is still bit-equal there. Not vacuous:
// quads of the slab leave out the outer rings with this bound too (checked by hand, marking them
// as SomeQuadsReadNoRingHere does: 2,753 channels of a 64² render).
TEST_F(TransmissionSkip, SlantedSlabToo) {
  const ImageRGBF cut = renderWith({}, slantedSlab(), slantedSlabScene());
  const ImageRGBF all = renderChanged(kCountLine, kAllRings, "slab-all", slantedSlab(), slantedSlabScene());
  ASSERT_EQ(cut.pixels.size(), all.pixels.size());
  EXPECT_EQ(differing(cut, all, 0.0f), 0);
}

// Its control: the bound on the chord's S (glow_scale(s0), the unslanted gather's) instead of the
// taps' own leaves out rings that carry light on the slab (measured: 24,633 channels differ; in
// a 64² render by up to 5e-4).
TEST_F(TransmissionSkip, ControlTheChordsScaleOnTheSlantedSlabChangesThePicture) {
  const ImageRGBF chordS = renderChanged(kTauLine, "float tau_inner = 0.5 * glow_scale(s0) * mm *", "slab-chord",
                                         slantedSlab(), slantedSlabScene());
  const ImageRGBF all = renderChanged(kCountLine, kAllRings, "slab-all", slantedSlab(), slantedSlabScene());
  const int n = differing(chordS, all, 0.0f);
  EXPECT_GT(n, 100) << "the slab's taps do not need the slanted S: the control shows nothing";
  std::cout << "[          ] bound on the chord's S: " << n << " channels differ\n";
}
