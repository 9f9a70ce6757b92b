// The vein model (issue 16) on the CPU: the batched rows equal the per-point reference, the
// parameters round-trip through preset files, and the structure measures of
// tests/vein_structure.h do what they claim on pictures whose answer is known.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "marble/core/error.h"
#include "marble/noise/marble_pattern.h"
#include "marble/scene/material_io.h"
#include "vein_structure.h"

namespace marble {
namespace {

TEST(VeinPattern, RowsAreBitIdenticalToThePointReference) {
  for (const char* preset : {"carrara", "rosso-levanto"}) {
    const Material m = loadPreset(preset);
    const glm::vec3 origin(-0.9f, 0.37f, -0.21f), step(0.013f, 0.0f, 0.0f);
    constexpr int n = 150;
    std::vector<glm::vec3> colours(n);
    std::vector<float> values(n);
    veinAlbedoRow(m, origin, step, n, colours.data(), values.data());
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p = origin + static_cast<float>(i) * step;
      const glm::vec3 c = veinAlbedo(m, p);
      ASSERT_EQ(std::memcmp(&c, &colours[static_cast<size_t>(i)], sizeof c), 0) << preset << " point " << i;
      ASSERT_EQ(values[static_cast<size_t>(i)], veinPatternValue(m, p)) << preset << " point " << i;
    }
  }
}

TEST(VeinPattern, MarbleAlbedoDispatchesOnTheModel) {
  Material m = loadPreset("carrara");
  const glm::vec3 p(0.2f, -0.3f, 0.4f), n(0, 0, 1);
  EXPECT_EQ(marbleAlbedo(m, p, n), veinAlbedo(m, p));
  m.vein_model = VeinModel::Paper;
  EXPECT_EQ(marbleAlbedo(m, p, n), patternColor(m, marblePatternValue(m, p, n)));
}

// Veins seen through the polish (pattern_core.glsl pat_cells_cover): k = 0 is the surface
// pattern exactly; a vein just beside a point shows there when the view ray runs towards it
// under the surface, not in an opaque stone (k very large: the surface only), and not when the
// ray runs away from it (negative control: a depth term that ignored the ray would show it
// both ways).
TEST(VeinPattern, BuriedVeinsShowAlongTheRayOnly) {
  const Material m = loadPreset("calacatta");
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 p(-0.8f + 0.03f * i, 0.1f, 0.2f);
    const glm::vec4 surface = veinShadeSeen(m, p, glm::vec3(0, 0, -1), 0.0f);
    const glm::vec3 c = veinAlbedo(m, p);
    ASSERT_EQ(std::memcmp(&surface, &c, sizeof c), 0) << i;
    ASSERT_EQ(surface.w, veinPatternValue(m, p)) << i;
  }
  // A ground point 0.01 beside the dominant vein at q (found along a line across the veins).
  int found = 0;
  for (int i = 0; i < 2000 && found < 3; ++i) {
    const glm::vec3 q(-0.9f + 0.0009f * i, -0.2f, 0.3f);
    if (veinPatternValue(m, q) > 0.05f) continue;  // the heart of a vein
    const glm::vec3 p = q - glm::vec3(0.0f, 0.012f, 0.0f);
    if (veinPatternValue(m, p) < 1.0f) continue;   // the ground, no vein of any family
    const glm::vec3 towards = glm::normalize(q - p + glm::vec3(0.003f, 0.0f, 0.0f));
    const float clear = veinShadeSeen(m, p, towards, 10.0f).w;
    const float opaque = veinShadeSeen(m, p, towards, 1e6f).w;
    const float away = veinShadeSeen(m, p, -towards, 10.0f).w;
    if (clear >= 1.0f) continue;  // this vein is of a finer family (not seen through) or ends here
    ++found;
    EXPECT_GT(opaque, 0.999f) << i;  // light that never goes deep sees the ground only
    EXPECT_GT(clear, 0.0f) << i;   // soft: not the vein's full cover
    EXPECT_EQ(away, 1.0f) << i;
  }
  EXPECT_EQ(found, 3);
}

TEST(VeinPattern, VeinsAreSomewhereAndNotEverywhere) {
  // A value that is never 0 or always 0 would pass the colour tests and show nothing.
  for (const char* preset : {"carrara", "nero-marquina", "emperador", "breccia-pernice"}) {
    const Material m = loadPreset(preset);
    int veins = 0, total = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x, ++total)
        veins += veinPatternValue(m, {-1.0f + x / 32.0f, -1.0f + y / 32.0f, 0.1f}) < 0.5f ? 1 : 0;
    EXPECT_GT(veins, total / 100) << preset;
    EXPECT_LT(veins, total / 2) << preset;
  }
}

// Breccia fragments come in many sizes (pattern_core.glsl, "breccia": the fragmentation
// cascade). On a 256 x 256 slice across [-1,1]^2 (no cracks: the matrix alone parts the
// fragments), the fragments -- 4-connected regions of value > 0.5 -- are counted per decade of
// area in pixels: [4, 40), [40, 400), [400, 4000). A breccia has fragments in every decade. The
// negative control is the same preset with fragment_split 0 (one size of cells, as before the
// cascade: crackle glaze), whose fragments crowd one or two decades; its smallest decade holds only the
// slivers where the slice grazes a cell's corner.
std::array<int, 3> fragmentsPerDecade(const Material& m) {
  constexpr int n = 256;
  std::vector<float> v(static_cast<size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    veinAlbedoRow(m, {-1.0f + 1.0f / n, -1.0f + (2.0f * y + 1.0f) / n, 0.1f}, {2.0f / n, 0.0f, 0.0f}, n, nullptr,
                  &v[static_cast<size_t>(y) * n]);
  std::vector<int> label(v.size(), 0);
  std::array<int, 3> decades{};
  std::vector<size_t> stack;
  for (size_t start = 0; start < v.size(); ++start) {
    if (label[start] || v[start] <= 0.5f) continue;
    int area = 0;
    stack.push_back(start);
    label[start] = 1;
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      ++area;
      const int x = static_cast<int>(i % n), y = static_cast<int>(i / n);
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= n || ny >= n) continue;
        const size_t j = static_cast<size_t>(ny) * n + nx;
        if (label[j] || v[j] <= 0.5f) continue;
        label[j] = 1;
        stack.push_back(j);
      }
    }
    if (area >= 4 && area < 4000) ++decades[static_cast<size_t>(std::log10(area / 4.0))];
  }
  return decades;
}

// Measured (2026-12-02, the four breccia presets): 28-169, 41-113, 16-17 fragments per decade
// with the cascade; 1-2, 5-15, 13-16 without. The pass mark: at least 20 in each of the two
// smaller decades and 5 in the largest.
bool manySizes(const std::array<int, 3>& d) { return d[0] >= 20 && d[1] >= 20 && d[2] >= 5; }

TEST(VeinPattern, BrecciaFragmentsComeInManySizes) {
  for (const char* preset : {"breccia-pernice", "emperador", "rosso-levanto", "verde-alpi"}) {
    Material m = loadPreset(preset);
    ASSERT_GT(m.fragment_split, 0.0f) << preset;
    m.vein_density = glm::vec3(m.vein_density.x, 0.0f, 0.0f);
    const std::array<int, 3> cascade = fragmentsPerDecade(m);
    m.fragment_split = 0.0f;
    const std::array<int, 3> oneSize = fragmentsPerDecade(m);
    std::printf("%s: fragments per decade of area (4-40, 40-400, 400-4000 px): %d %d %d; without the cascade %d %d %d\n",
                preset, cascade[0], cascade[1], cascade[2], oneSize[0], oneSize[1], oneSize[2]);
    EXPECT_TRUE(manySizes(cascade)) << preset;
    EXPECT_FALSE(manySizes(oneSize)) << preset << ": the negative control";
  }
}

TEST(VeinPattern, ParametersRoundTripThroughPresetFiles) {
  Material m = loadPreset("verde-alpi");
  setMaterialKey(m, "vein_spacing", "0.5,0.25,0.125");
  setMaterialKey(m, "vein_normal", "0,1,0");
  setMaterialKey(m, "vein_model", "network");
  setMaterialKey(m, "fragment_tint", "0.25");
  const auto path = std::filesystem::temp_directory_path() / ("marble-vein-roundtrip-" + std::to_string(::getpid()) + ".json");
  saveMaterial(path, m);
  EXPECT_EQ(loadPreset(path.string()), m);
  std::filesystem::remove(path);
  EXPECT_THROW(setMaterialKey(m, "vein_model", "swirl"), InputError);
  EXPECT_THROW(setMaterialKey(m, "vein_normal", "0,0,0"), InputError);
  EXPECT_THROW(setMaterialKey(m, "vein_density", "0.5,0.5,2"), InputError);
}

// ---- the structure measures on known pictures ----

std::vector<float> blank(int n) { return std::vector<float>(static_cast<size_t>(n) * n, 1.0f); }
void disc(std::vector<float>& v, int n, float cx, float cy, float r, float value = 0.0f) {
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) v[static_cast<size_t>(y) * n + x] = value;
}
// A band of half-width r along the segment a-b.
void band(std::vector<float>& v, int n, glm::vec2 a, glm::vec2 b, float r) {
  const int steps = static_cast<int>(glm::length(b - a) * 2.0f) + 1;
  for (int i = 0; i <= steps; ++i) {
    const glm::vec2 p = a + (b - a) * (static_cast<float>(i) / steps);
    disc(v, n, p.x, p.y, r);
  }
}

TEST(VeinStructureMeasure, ConstantWidthLinesAcrossThePictureHaveNoForksNoEndsNoWidthChange) {
  constexpr int n = 200;
  std::vector<float> v = blank(n);
  for (int k = 0; k < 4; ++k) band(v, n, {-5.0f, 20.0f + 45.0f * k}, {n + 5.0f, 40.0f + 45.0f * k}, 3.0f);
  const test::VeinStructure s = test::measureVeins(v, n, n);
  SCOPED_TRACE(::testing::Message() << "junctions " << s.junctions << ", inner endings " << s.innerEndings << ", width CV "
                                    << s.widthCv << " over " << s.veinsMeasured << " veins");
  EXPECT_EQ(s.junctions, 0);
  EXPECT_EQ(s.innerEndings, 0);
  EXPECT_LT(s.widthCv, 0.1);
  EXPECT_GE(s.veinsMeasured, 4);
}

TEST(VeinStructureMeasure, RingsWithBumpsAndPinholesDoNotCountAsBranching) {
  // What contour bands look like: closed, with a bump (a spur) and a pinhole (a loop).
  constexpr int n = 200;
  std::vector<float> v = blank(n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float r = std::hypot(x - 100.0f, y - 100.0f);
      if (std::abs(r - 60.0f) < 4.0f) v[static_cast<size_t>(y) * n + x] = 0.0f;
    }
  disc(v, n, 100.0f, 36.0f, 5.0f);            // a bump on the outside
  disc(v, n, 160.0f, 100.0f, 1.5f, 1.0f);     // a pinhole in the band
  const test::VeinStructure s = test::measureVeins(v, n, n);
  SCOPED_TRACE(::testing::Message() << "junctions " << s.junctions << ", inner endings " << s.innerEndings << ", width CV "
                                    << s.widthCv << " over " << s.veinsMeasured << " veins");
  EXPECT_EQ(s.junctions, 0);
  EXPECT_EQ(s.innerEndings, 0);
}

TEST(VeinStructureMeasure, AForkAnEndAndASwellAreSeen) {
  constexpr int n = 200;
  std::vector<float> v = blank(n);
  band(v, n, {-5.0f, 100.0f}, {100.0f, 100.0f}, 2.0f);  // from the border to the fork
  band(v, n, {100.0f, 100.0f}, {205.0f, 40.0f}, 2.0f);  // one arm back to the border
  band(v, n, {100.0f, 100.0f}, {160.0f, 160.0f}, 2.0f);  // the other ends inside
  disc(v, n, 50.0f, 100.0f, 7.0f);                      // a swell on each
  disc(v, n, 150.0f, 72.0f, 7.0f);
  disc(v, n, 135.0f, 135.0f, 7.0f);
  const test::VeinStructure s = test::measureVeins(v, n, n);
  SCOPED_TRACE(::testing::Message() << "junctions " << s.junctions << ", inner endings " << s.innerEndings << ", width CV "
                                    << s.widthCv << " over " << s.veinsMeasured << " veins");
  EXPECT_EQ(s.junctions, 1);
  EXPECT_EQ(s.innerEndings, 1);
  EXPECT_GT(s.widthCv, 0.2);
}

}  // namespace
}  // namespace marble
