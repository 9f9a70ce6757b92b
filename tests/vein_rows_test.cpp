// The vein model's batched rows (the fast CPU path: marble_pattern.cpp's row memo,
// noise/row_memo.inc, and on AVX2 the 8-lane build, noise/vein_lanes.inc) against the
// per-point reference on random rows of every stone preset:
// veinAlbedoRow equals veinAlbedo bit for bit, and AlbedoSampler::veinRow (turbulence from the
// baked grid) equals the sampler at each point bit for bit. Negative controls: another seed's
// rows, or another seed's grid, are told apart at most points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "marble/noise/lanes.h"
#include "marble/noise/marble_pattern.h"
#include "marble/scene/embedded_presets.h"
#include "marble/scene/material_io.h"

namespace marble {
namespace {

// Every preset with a vein model (issue 16), by name: presets added later are covered too.
std::vector<std::string> stonePresets() {
  std::vector<std::string> names;
  for (const auto& [file, text] : embeddedPresets()) {
    const std::string name = file.substr(0, file.size() - 5);  // "carrara.json" -> "carrara"
    if (loadPreset(name).vein_model != VeinModel::Paper) names.push_back(name);
  }
  return names;
}

struct Row {
  glm::vec3 origin, step;
  int count;
};

// Random rows over and beyond the object ([-1.5, 1.5]^3, negative coordinates included): most
// along x (the fast path), some along x backwards or with a tiny step (many points per cell),
// and some along arbitrary directions (the general path).
std::vector<Row> randomRows(uint32_t seed, int rows) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-1.5f, 1.5f), unit(-1.0f, 1.0f), logStep(-4.0f, -1.3f);
  std::uniform_int_distribution<int> count(1, 200), kind(0, 5);
  std::vector<Row> out;
  for (int r = 0; r < rows; ++r) {
    Row row{{pos(rng), pos(rng), pos(rng)}, {}, count(rng)};
    const float step = std::pow(10.0f, logStep(rng));
    const int k = kind(rng);
    if (k <= 3)
      row.step = glm::vec3(step, 0.0f, 0.0f);
    else if (k == 4)
      row.step = glm::vec3(-step, 0.0f, 0.0f);
    else
      row.step = step * glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f));
    out.push_back(row);
  }
  return out;
}

struct Agreement {
  int points = 0;
  int different = 0;  // points whose colour or value differ in any bit
};

// rowFn(row, colours, values) against pointFn(p) -> vec4 (colour, value).
template <typename RowFn, typename PointFn>
Agreement compareRows(const std::vector<Row>& rows, RowFn rowFn, PointFn pointFn) {
  Agreement a;
  for (const Row& row : rows) {
    std::vector<glm::vec3> colours(static_cast<size_t>(row.count));
    std::vector<float> values(static_cast<size_t>(row.count));
    rowFn(row, colours.data(), values.data());
    for (int i = 0; i < row.count; ++i) {
      const glm::vec3 p = row.origin + static_cast<float>(i) * row.step;
      const glm::vec4 want = pointFn(p);
      const glm::vec3 wantColour(want.x, want.y, want.z);
      ++a.points;
      if (std::memcmp(&wantColour, &colours[static_cast<size_t>(i)], sizeof wantColour) != 0 ||
          (!std::isnan(want.w) && std::memcmp(&want.w, &values[static_cast<size_t>(i)], sizeof want.w) != 0))
        ++a.different;
    }
  }
  return a;
}

// The lanes' builds this CPU runs (vein_lanes.inc's shadeBatch): the AVX-512 one where it has
// it, and the AVX2 one always (switched to for the test). Each equality test below runs on each.
struct LaneBuild {
  bool wide;
  const char* name;
};
std::vector<LaneBuild> laneBuilds() {
  std::vector<LaneBuild> builds;
  setVeinRowsWideLanes(true);
  if (veinRowsUseWideLanes()) builds.push_back({true, "AVX-512 build"});
  builds.push_back({false, "AVX2 build (or no lanes)"});
  return builds;
}
// Sets the build for a scope, back to the default (the widest) after.
struct UseLaneBuild {
  explicit UseLaneBuild(const LaneBuild& b) : trace(__FILE__, __LINE__, b.name) { setVeinRowsWideLanes(b.wide); }
  ~UseLaneBuild() { setVeinRowsWideLanes(true); }
  UseLaneBuild(const UseLaneBuild&) = delete;
  UseLaneBuild& operator=(const UseLaneBuild&) = delete;
  testing::ScopedTrace trace;
};

glm::vec4 reference(const Material& m, glm::vec3 p) {
  const glm::vec3 c = veinAlbedo(m, p);
  return glm::vec4(c, veinPatternValue(m, p));
}

TEST(VeinRows, EqualThePointReferenceBitForBitOnRandomRows) {
  for (const LaneBuild& build : laneBuilds()) {
    const UseLaneBuild use(build);
    const std::vector<std::string> presets = stonePresets();
    ASSERT_GE(presets.size(), 7u);  // issue 16's stones and a breccia
    uint32_t seed = 1;
    for (const std::string& name : presets) {
      const Material m = loadPreset(name);
      const std::vector<Row> rows = randomRows(seed++, 12);
      const Agreement a = compareRows(
          rows, [&](const Row& r, glm::vec3* c, float* v) { veinAlbedoRow(m, r.origin, r.step, r.count, c, v); },
          [&](glm::vec3 p) { return reference(m, p); });
      EXPECT_GT(a.points, 500) << name;
      EXPECT_EQ(a.different, 0) << name << ": " << a.different << " of " << a.points << " points differ";
      // Negative control: the same rows of the stone with another seed are another stone.
      Material other = m;
      other.seed += 1;
      const Agreement n = compareRows(
          rows, [&](const Row& r, glm::vec3* c, float* v) { veinAlbedoRow(other, r.origin, r.step, r.count, c, v); },
          [&](glm::vec3 p) { return reference(m, p); });
      EXPECT_GT(n.different, n.points / 2) << name;
    }
  }
}

// Outside the presets' values: Perlin's basis (turbulence per point), a seed with the high bit
// set, a single octave, a vein normal along x (stretch along the row), breccia and network.
TEST(VeinRows, EqualThePointReferenceForOtherParameters) {
  for (const LaneBuild& build : laneBuilds()) {
    const UseLaneBuild use(build);
    Material base = loadPreset("carrara");
    std::vector<Material> cases;
    Material perlin = base;
    perlin.basis = NoiseBasis::Perlin;
    cases.push_back(perlin);
    Material seed = base;
    seed.seed = 0x9abcdef0u;
    cases.push_back(seed);
    Material one = base;
    one.turb_size = 2.0f;
    one.resolution = 64;
    cases.push_back(one);
    Material along = base;
    along.vein_normal = glm::vec3(1.0f, 0.0f, 0.0f);
    along.vein_stretch = 4.0f;
    cases.push_back(along);
    Material breccia = base;
    breccia.vein_model = VeinModel::Breccia;
    breccia.fragment_tint = 0.8f;
    cases.push_back(breccia);
    for (size_t k = 0; k < cases.size(); ++k) {
      const Material& m = cases[k];
      const Agreement a = compareRows(
          randomRows(100 + static_cast<uint32_t>(k), 8),
          [&](const Row& r, glm::vec3* c, float* v) { veinAlbedoRow(m, r.origin, r.step, r.count, c, v); },
          [&](glm::vec3 p) { return reference(m, p); });
      EXPECT_EQ(a.different, 0) << "case " << k << ": " << a.different << " of " << a.points;
    }
  }
}

// A stone whose grid is small enough to bake in a test (64 texels: 32^3 grid texels).
Material smallGridStone(const std::string& preset) {
  Material m = loadPreset(preset);
  m.resolution = 64;
  m.turb_size = 16.0f;
  return m;
}

TEST(VeinRows, GridRowsEqualTheGridSamplerBitForBit) {
  for (const LaneBuild& build : laneBuilds()) {
    const UseLaneBuild use(build);
    for (const char* preset : {"carrara", "calacatta", "rosso-levanto", "breccia-pernice"}) {
      const Material m = smallGridStone(preset);
      const AlbedoSampler sampler(m, 1e12);
      ASSERT_TRUE(sampler.usesGrid()) << preset;
      const std::vector<Row> rows = randomRows(7, 16);
      const glm::vec3 n(0.0f, 0.0f, 1.0f);  // read by the paper's triplanar mapping only
      const Agreement a = compareRows(
          rows, [&](const Row& r, glm::vec3* c, float* v) { sampler.veinRow(r.origin, r.step, r.count, c, v); },
          [&](glm::vec3 p) { return glm::vec4(sampler(p, n), NAN); });  // the sampler gives no value
      EXPECT_GT(a.points, 500) << preset;
      EXPECT_EQ(a.different, 0) << preset << ": " << a.different << " of " << a.points;
      // And within the grid's exactness of the evaluated reference: its turbulence is within half
      // a 16-bit step (TurbulenceGrid tests), which moves a vein's edge by ~1e-5 of the warp; on
      // the steepest edges (calacatta's) that is 2.3e-3 in linear colour, never more than one
      // level of 8-bit sRGB (AlbedoSampler's test, on other points).
      float worst = 0.0f;
      int offByMoreThanOneLevel = 0;
      auto byte = [](float c) {
        c = std::clamp(c, 0.0f, 1.0f);
        return std::lround((c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f) * 255.0f);
      };
      for (const Row& r : rows) {
        std::vector<glm::vec3> c(static_cast<size_t>(r.count));
        sampler.veinRow(r.origin, r.step, r.count, c.data(), nullptr);
        for (int i = 0; i < r.count; ++i) {
          const glm::vec3 got = c[static_cast<size_t>(i)];
          const glm::vec3 want = veinAlbedo(m, r.origin + static_cast<float>(i) * r.step);
          for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, std::fabs(got[k] - want[k]));
            if (std::abs(byte(got[k]) - byte(want[k])) > 1) ++offByMoreThanOneLevel;
          }
        }
      }
      EXPECT_LT(worst, 5e-3f) << preset;
      EXPECT_EQ(offByMoreThanOneLevel, 0) << preset << " (worst linear difference " << worst << ")";
      // Negative control: another seed's grid under the same stone is told apart.
      Material other = m;
      other.seed += 1;
      const AlbedoSampler otherSampler(other, 1e12);
      const Agreement na = compareRows(
          rows, [&](const Row& r, glm::vec3* c, float* v) { otherSampler.veinRow(r.origin, r.step, r.count, c, v); },
          [&](glm::vec3 p) { return glm::vec4(sampler(p, n), NAN); });
      EXPECT_GT(na.different, na.points / 2) << preset;
    }
  }
}

TEST(VeinRows, GridRowsWithoutAGridAreTheEvaluatedRows) {
  const Material m = smallGridStone("carrara");
  const AlbedoSampler few(m, 10.0);  // too few points to pay for a grid
  ASSERT_FALSE(few.usesGrid());
  const Agreement a = compareRows(
      randomRows(3, 6), [&](const Row& r, glm::vec3* c, float* v) { few.veinRow(r.origin, r.step, r.count, c, v); },
      [&](glm::vec3 p) { return reference(m, p); });
  EXPECT_EQ(a.different, 0);
  Material paper = m;
  paper.vein_model = VeinModel::Paper;
  glm::vec3 c;
  float v;
  EXPECT_THROW(AlbedoSampler(paper, 1e12).veinRow(glm::vec3(0.0f), glm::vec3(0.1f, 0.0f, 0.0f), 1, &c, &v),
               std::logic_error);
}

// The lanes' branch check (noise/lanes.h), which keeps the 8-lane rows exact: a comparison
// whose lanes agree converts to bool silently; one whose lanes disagree is recorded.
TEST(VeinRows, LanesRecordABranchTheirLanesTakeDifferently) {
  const float values[simd::kLanes] = {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f};
  simd::LaneF x;
  std::memcpy(&x.v, values, sizeof values);
  simd::laneDivergence = false;
  EXPECT_TRUE(static_cast<bool>(x >= 0.0f));
  EXPECT_FALSE(static_cast<bool>(x > 7.0f));
  EXPECT_FALSE(simd::laneDivergence);
  static_cast<void>(static_cast<bool>(x < 4.0f));  // no right answer for all lanes...
  EXPECT_TRUE(simd::laneDivergence);                // ...so the disagreement is recorded
  simd::laneDivergence = false;
}

// The rows shade on the AVX-512 build exactly where the CPU has AVX-512 F, VL, BW and DQ (the
// equality tests above then check both builds), and the switch turns it off.
TEST(VeinRows, RowsShadeOnTheAvx512BuildWhereTheCpuHasIt) {
#if defined(__x86_64__) && !defined(__clang__)
  const bool avx512 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
                      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512dq");
#else
  const bool avx512 = false;  // the library builds it with GCC on x86-64 only
#endif
  EXPECT_EQ(veinRowsUseWideLanes(), avx512);
  setVeinRowsWideLanes(false);
  EXPECT_FALSE(veinRowsUseWideLanes());
  setVeinRowsWideLanes(true);
  EXPECT_EQ(laneBuilds().size(), avx512 ? 2u : 1u);
}

// The equality tests above mean something for the lanes only where the lanes ran: on an AVX2
// CPU a network stone's rows go through them (its point-dependent branches are selects, so
// few batches fall back), and a breccia's branches on its fragments make some batches diverge
// (recomputed one point at a time: its equality above covers that path). Without AVX2 every
// point is shaded one at a time.
TEST(VeinRows, RowsRunThroughTheLanesWhereTheCpuHasThem) {
  auto shadeRows = [](const Material& m) {
    const VeinRowCounts before = veinRowCounts();
    std::vector<glm::vec3> colours(256);
    std::vector<float> values(256);
    for (int r = 0; r < 32; ++r)
      veinAlbedoRow(m, glm::vec3(-1.0f, static_cast<float>(r) / 16.0f - 1.0f, 0.3f), glm::vec3(1.0f / 128.0f, 0.0f, 0.0f),
                    256, colours.data(), values.data());
    const VeinRowCounts after = veinRowCounts();
    return VeinRowCounts{after.laneBatches - before.laneBatches, after.divergedBatches - before.divergedBatches,
                         after.singlePoints - before.singlePoints};
  };
  const VeinRowCounts network = shadeRows(loadPreset("carrara"));
  const VeinRowCounts breccia = shadeRows(loadPreset("breccia-pernice"));
  if (veinRowsUseLanes()) {
    EXPECT_EQ(network.laneBatches, 32 * 256 / simd::kLanes);
    EXPECT_EQ(network.singlePoints, 0);
    EXPECT_LT(network.divergedBatches, network.laneBatches / 20);
    EXPECT_GT(breccia.divergedBatches, 0);
  } else {
    EXPECT_EQ(network.laneBatches, 0);
    EXPECT_EQ(network.singlePoints, 32 * 256);
  }
}

}  // namespace
}  // namespace marble
