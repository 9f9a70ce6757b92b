// `marble texture` output of every stone preset reads as veins of real stone (issue 16), by the
// measures of tests/vein_structure.h: the network branches, veins vary in width along their
// length, and veins end inside the picture. Negative controls: the presets as they were before
// the vein model (tests/fixtures/contour-presets: contour lines of |sin(ramp + turbulence)|)
// must fail the branching test; and a swatch written without --tile shows its seam.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli_support.h"
#include "marble/core/image.h"
#include "marble/scene/material_io.h"
#include "vein_structure.h"

namespace marble {
namespace {

using test::measureVeins;
using test::runMarble;
using test::tempDir;
using test::VeinStructure;

// Thresholds, from the figures these tests print (docs/materials.md "Vein model" lists them): at
// 256 px the stone presets measured 9.9-26 junctions per 1000 skeleton pixels, the contour
// presets 0-7.3 (old nero-marquina, whose bands merge at saddles, the highest); width CV 0.16-0.57.
constexpr double kMinBranching = 8.0;
constexpr double kMinWidthCv = 0.15;
constexpr int kMinInnerEndings = 4;
constexpr int kSize = 256;

std::vector<float> greyOf(const ImageRGBA8& img) {
  std::vector<float> v(static_cast<size_t>(img.width) * img.height);
  for (size_t i = 0; i < v.size(); ++i) v[i] = img.pixels[i * 4] / 255.0f;
  return v;
}

VeinStructure measureTexture(const std::string& preset, const char* file, const std::string& dirName) {
  const Material m = loadPreset(preset);
  // Where the colour is nearer the vein's: the vein models' coverage 0.5; the paper's ramp midpoint.
  const float threshold = m.vein_model == VeinModel::Paper ? std::pow(0.5f, m.vein_sharpness) : 0.5f;
  const auto dir = tempDir(dirName);
  const auto r = runMarble("texture -o " + dir.string() + " --preset " + preset + " --size " + std::to_string(kSize));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(dir / file);
  const VeinStructure s = measureVeins(greyOf(img), img.width, img.height, threshold);
  std::cout << preset << ": skeleton " << s.skeletonPixels << " px, " << s.junctions << " junctions = "
            << s.junctionsPer1000 << " per 1000 px; width CV " << s.widthCv << " over " << s.veinsMeasured
            << " veins; " << s.innerEndings << " inner endings\n";
  return s;
}

std::vector<std::string> stonePresets() {
  std::vector<std::string> names;
  for (const auto& p : builtinPresets())
    if (p.name != "paper" && p.name != "paper-program") names.push_back(p.name);  // the paper's two: its veins
  return names;
}

TEST(VeinStructureCli, EveryStonePresetBranchesVariesInWidthAndHasVeinsThatEnd) {
  const auto names = stonePresets();
  ASSERT_GE(names.size(), 8u);
  for (const auto& name : names) {
    ASSERT_NE(loadPreset(name).vein_model, VeinModel::Paper) << name << " is a stone preset";
    const VeinStructure s = measureTexture(name, "veins.png", "veins-" + name);
    EXPECT_GE(s.junctionsPer1000, kMinBranching) << name << ": a network forks";
    EXPECT_GE(s.widthCv, kMinWidthCv) << name << ": veins swell and pinch";
    EXPECT_GE(s.innerEndings, kMinInnerEndings) << name << ": veins fade out inside the stone";
  }
}

TEST(VeinStructureCli, ContourLinePresetsFailTheBranchingTest) {
  // Negative control: the stone presets as they were (|sin(ramp + turbulence)|).
  const auto dir = std::filesystem::path(MARBLE_TEST_FIXTURES) / "contour-presets";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const VeinStructure s = measureTexture(entry.path().string(), "sine.png", "contour-" + entry.path().stem().string());
    EXPECT_LT(s.junctionsPer1000, kMinBranching) << entry.path() << ": contour lines do not fork";
    ++n;
  }
  EXPECT_GE(n, 5);
}

// The mean absolute difference between neighbouring pixels (all channels) across each vertical
// and horizontal line between pixels: `seam` is the mean of the two wrap-around lines (last
// column to first, last row to first), `interior` the 90th percentile of the other lines -- an
// exactly periodic texture's seam is just one more line, so it may exceed the mean by chance.
struct SeamGradient {
  double seam = 0, interior = 0, interiorMedian = 0;
};
SeamGradient seamGradient(const ImageRGBA8& img) {
  const int w = img.width, h = img.height;
  auto px = [&](int x, int y, int c) { return static_cast<double>(img.pixels[(static_cast<size_t>(y) * w + x) * 4 + c]); };
  std::vector<double> lines;
  double seam = 0;
  for (int x = 0; x < w; ++x) {  // the line between column x and x + 1 (wrapping)
    double sum = 0;
    for (int y = 0; y < h; ++y)
      for (int c = 0; c < 3; ++c) sum += std::abs(px((x + 1) % w, y, c) - px(x, y, c));
    (x == w - 1 ? seam : lines.emplace_back()) += sum / (3.0 * h);
  }
  for (int y = 0; y < h; ++y) {
    double sum = 0;
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) sum += std::abs(px(x, (y + 1) % h, c) - px(x, y, c));
    (y == h - 1 ? seam : lines.emplace_back()) += sum / (3.0 * w);
  }
  std::sort(lines.begin(), lines.end());
  return {seam / 2.0, lines[lines.size() * 9 / 10], lines[lines.size() / 2]};
}

SeamGradient textureSeam(const std::string& preset, bool tile) {
  const auto dir = tempDir("tile-" + preset + (tile ? "-t" : "-n"));
  const auto r = runMarble("texture -o " + dir.string() + " --preset " + preset + " --size 128" + (tile ? " --tile" : ""));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const SeamGradient g = seamGradient(readPng(dir / "marble.png"));
  std::cout << preset << (tile ? " --tile" : "") << ": seam gradient " << g.seam << ", interior lines' 90th percentile "
            << g.interior << ", median " << g.interiorMedian << "\n";
  return g;
}

TEST(VeinStructureCli, EveryPresetTilesWithoutASeam) {
  for (const auto& p : builtinPresets()) {
    const SeamGradient g = textureSeam(p.name, true);
    EXPECT_LE(g.seam, g.interior) << p.name;
  }
}

TEST(VeinStructureCli, WithoutTileASliceShowsItsSeam) {
  // Negative control for the seam measure: a plain slice does not wrap around.
  const SeamGradient g = textureSeam("breccia-pernice", false);
  EXPECT_GT(g.seam, 1.5 * g.interiorMedian);
  EXPECT_GT(g.seam, g.interior);
}

TEST(VeinStructureCli, SliceOptionMovesThePlaneAndRejectsBadInput) {
  const auto dir = tempDir("slice");
  ASSERT_EQ(runMarble("texture -o " + (dir / "a").string() + " --preset carrara --size 32 --slice z=0").exitCode, 0);
  ASSERT_EQ(runMarble("texture -o " + (dir / "b").string() + " --preset carrara --size 32 --slice x=0.3").exitCode, 0);
  EXPECT_NE(readPng(dir / "a" / "marble.png").pixels, readPng(dir / "b" / "marble.png").pixels);
  const auto bad = runMarble("texture -o " + (dir / "c").string() + " --preset carrara --slice w=1");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--slice: w=1: expected AXIS=OFFSET"), std::string::npos) << bad.output;
  const auto paper = runMarble("texture -o " + (dir / "d").string() + " --preset paper --slice z=0");
  EXPECT_EQ(paper.exitCode, 2);
  EXPECT_NE(paper.output.find("the paper's texture is 2D"), std::string::npos) << paper.output;
}

TEST(VeinStructureCli, PaperTextureIsExactlyAsBefore) {
  // tests/golden/texture-paper: written by `marble texture --preset paper --size 128` before the
  // vein model existed (tools/update-goldens.sh rewrites it on purpose). Byte for byte.
  const auto golden = std::filesystem::path(MARBLE_TEST_FIXTURES) / ".." / "golden" / "texture-paper";
  const auto dir = tempDir("paper-texture");
  for (const std::string extra : {"", " --tile"}) {
    ASSERT_EQ(runMarble("texture -o " + dir.string() + " --preset paper --size 128" + extra).exitCode, 0);
    for (const char* file : {"white_noise.png", "smooth_noise.png", "turbulence.png", "sine.png", "marble.png"})
      EXPECT_EQ(readPng(dir / file).pixels, readPng(golden / file).pixels) << file << extra;
  }
}

}  // namespace
}  // namespace marble
