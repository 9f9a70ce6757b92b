// `marble bake` and `marble export` end to end: the files a user gets, bad input (one line, exit
// 2, nothing written), deterministic bytes, texture coordinates surviving a round trip through
// .glb, and the Khronos glTF-Validator's verdict (tools/web, installed by tools/setup-web-tools.sh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "marble/bake/uv_raster.h"
#include "marble/core/image.h"
#include "marble/mesh/mesh.h"

namespace {

namespace fs = std::filesystem;
using marble::test::runMarble;
using marble::test::tempDir;

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void spit(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

size_t lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// The validator's JSON report for `file`, or null (and a reason) when the tools are missing.
nlohmann::json validate(const fs::path& file, std::string& why) {
  const fs::path tools = fs::path(MARBLE_SOURCE_DIR) / "tools" / "web";
  if (!fs::exists(tools / "node_modules" / "gltf-validator") || std::system("node --version > /dev/null 2>&1") != 0) {
    why = "the glTF-Validator is not installed (tools/setup-web-tools.sh installs node's gltf-validator into tools/web)";
    return nullptr;
  }
  const fs::path report = file.string() + ".report.json";
  const std::string cmd = "node " + (tools / "validate.mjs").string() + " " + file.string() + " > " + report.string();
  if (std::system(cmd.c_str()) != 0) {
    why = "the validator failed to run: " + cmd;
    return nullptr;
  }
  return nlohmann::json::parse(slurp(report));
}

// Skips (or fails where the project's scripts promised the tools, MARBLE_REQUIRE_WEB_TOOLS=1).
#define VALIDATE_OR_SKIP(report, file)                                                    \
  std::string why_;                                                                       \
  const nlohmann::json report = validate(file, why_);                                     \
  if (report.is_null()) {                                                                 \
    if (std::getenv("MARBLE_REQUIRE_WEB_TOOLS")) FAIL() << why_;                          \
    GTEST_SKIP() << why_;                                                                 \
  }

void expectClean(const nlohmann::json& report) {
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"].dump(1);
}

}  // namespace

TEST(BakeCli, WritesTheTextureSet) {
  const auto scratch = tempDir("bake-set");
  const fs::path dir = scratch / "out";
  const auto r = runMarble("bake builtin:sphere -o " + dir.string() + " --size 64 --preset carrara");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("unwrapped"), std::string::npos) << r.output;
  for (const char* f : {"base_color.png", "metallic_roughness.png", "thickness.png", "thickness.exr", "material.json"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  const auto j = nlohmann::json::parse(slurp(dir / "material.json"));
  // thickness.exr: the PNG's map unquantized, in millimetres (the sphere's is 2 units x 100 mm
  // across, its mean chord 4/3 of the radius: 133 mm), equal to the PNG within its 1/255 steps.
  const marble::ImageRGBF mm = marble::readExr(dir / "thickness.exr");
  const marble::ImageRGBA8 png8 = marble::readPng(dir / "thickness.png");
  ASSERT_EQ(mm.width, png8.width);
  const double scaleMm = j["textures"]["thickness"]["scale_mm"].get<double>();
  float largest = 0;
  for (int i = 0; i < mm.width * mm.height; ++i) {
    largest = std::max(largest, mm.pixels[static_cast<size_t>(i) * 3]);
    EXPECT_NEAR(mm.pixels[static_cast<size_t>(i) * 3], png8.pixels[static_cast<size_t>(i) * 4] / 255.0 * scaleMm, 0.51 / 255.0 * scaleMm) << i;
  }
  EXPECT_NEAR(largest, scaleMm, 1e-3 * scaleMm);
  EXPECT_EQ(j["textures"]["thickness_mm"]["file"], "thickness.exr");
  EXPECT_EQ(j["textures"]["base_color"]["size"], 64);
  EXPECT_EQ(j["textures"]["thickness"]["size"], 64);  // a quarter, at least 64
  EXPECT_NEAR(j["textures"]["thickness"]["scale_units"].get<double>(), 4.0 / 3.0, 0.05);  // the sphere's closed form
  EXPECT_EQ(j["uv"]["source"], "unwrap");
  EXPECT_EQ(j["material"]["name"], "carrara");
  const marble::ImageRGBA8 img = marble::readPng(dir / "base_color.png");
  EXPECT_EQ(img.width, 64);
}

TEST(BakeCli, BadInputIsOneLineExitTwoAndNothingWritten) {
  const auto base = tempDir("bake-bad");
  spit(base / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  // Two triangles on the same texture coordinates.
  spit(base / "overlap.obj",
       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/2\n");
  spit(base / "afile", "x");
  spit(base / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"bake " + (base / "points.obj").string() + " -o " + (base / "o1").string(), "no faces"},
      {"bake " + (base / "overlap.obj").string() + " --uv-from file -o " + (base / "o2").string(), "overlap"},
      {"bake " + (base / "overlap.obj").string() + " --size 4 -o " + (base / "o3").string(), "--size"},
      {"bake " + (base / "overlap.obj").string() + " --size 9000 -o " + (base / "o4").string(), "--size"},
      {"bake " + (base / "overlap.obj").string() + " --uv-from maybe -o " + (base / "o5").string(), "--uv-from"},
      {"bake " + (base / "tri.obj").string() + " -o " + (base / "afile" / "sub").string(), "is not a folder"},
      {"export " + (base / "overlap.obj").string() + " -o " + (base / "model.fbx").string(), "expected a .glb or .gltf"},
      {"export " + (base / "tri.obj").string() + " -o " + (base / "afile" / "m.glb").string(), "does not exist"},
      {"export " + (base / "points.obj").string() + " -o " + (base / "m.glb").string(), "no faces"},
  };
  for (const Case& c : cases) {
    const auto r = runMarble(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
    EXPECT_EQ(lines(r.output), 1u) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
  for (const char* o : {"o1", "o2", "o3", "o4", "o5", "model.fbx", "m.glb"}) EXPECT_FALSE(fs::exists(base / o)) << o;
}

TEST(ExportCli, SameInputSameBytesAndTheValidatorIsSatisfied) {
  const auto dir = tempDir("export-det");
  const fs::path scene = dir / "scene.json";
  spit(scene, R"({"mesh": "builtin:torus", "material": {"preset": "nero-marquina"}})");
  for (const char* ext : {".glb", ".gltf"}) {
    const fs::path a = dir / (std::string("a") + ext), b = dir / (std::string("b") + ext);
    ASSERT_EQ(runMarble("export " + scene.string() + " --size 128 -o " + a.string()).exitCode, 0);
    ASSERT_EQ(runMarble("export " + scene.string() + " --size 128 -o " + b.string()).exitCode, 0);
    EXPECT_EQ(slurp(a), slurp(b)) << ext;
  }
  VALIDATE_OR_SKIP(glb, dir / "a.glb");
  expectClean(glb);
  const nlohmann::json gltf = validate(dir / "a.gltf", why_);
  expectClean(gltf);
}

TEST(ExportCli, TextureCoordinatesSurviveAGlbRoundTrip) {
  // An export's own texcoords are read back (TEXCOORD_0, v flipped twice) and kept by --uv-from
  // file: the second export has the first one's layout, and validates too.
  const auto dir = tempDir("export-uv");
  spit(dir / "scene.json", R"({"mesh": "builtin:sculpture"})");
  ASSERT_EQ(runMarble("export " + (dir / "scene.json").string() + " --size 128 -o " + (dir / "first.glb").string()).exitCode, 0);
  const auto r = runMarble("export " + (dir / "first.glb").string() + " --uv-from file --size 128 -o " + (dir / "second.glb").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("the file's texture coordinates"), std::string::npos) << r.output;
  const marble::Mesh first = marble::loadMesh(dir / "first.glb"), second = marble::loadMesh(dir / "second.glb");
  ASSERT_EQ(first.texcoords.size(), second.texcoords.size());
  for (size_t i = 0; i < first.texcoords.size(); ++i) ASSERT_EQ(first.texcoords[i], second.texcoords[i]) << i;
  EXPECT_EQ(marble::measureUvOverlap(first, 512).overlapSamples, 0u);
  VALIDATE_OR_SKIP(report, dir / "second.glb");
  expectClean(report);
}

TEST(ExportCli, AMeshWoundInwardIsWrittenWoundOutward) {
  // glTF viewers cull back faces (and a volume must not be double-sided): a tetrahedron wound
  // inward comes out wound outward, with normals that agree.
  const auto dir = tempDir("export-winding");
  spit(dir / "inward.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  ASSERT_LT(marble::signedVolume(marble::loadMesh(dir / "inward.obj")), 0.0);  // the fixture is what it says
  ASSERT_EQ(runMarble("export " + (dir / "inward.obj").string() + " --size 32 -o " + (dir / "out.glb").string()).exitCode, 0);
  const marble::Mesh m = marble::loadMesh(dir / "out.glb");
  EXPECT_GT(marble::signedVolume(m), 0.0);
  // Vertex normals point the way the triangles face.
  double agreement = 0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    agreement += glm::dot(glm::cross(b - a, c - a), m.normals[m.indices[t]]);
  }
  EXPECT_GT(agreement, 0.0);
}
