// `marble render` and friends end to end: exit codes, one-line messages, and the picture.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_support.h"
#include "hdr_support.h"
#include "marble/core/image.h"

using namespace marble;
using namespace marble::test;

namespace {

void writeFile(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// The default (showcase) scene stands in a studio with a floor; these tests find the object
// against a flat background, so they pin the stage off and the paper's brown background.
const std::string kFlatStage = " --ground off --backdrop off --background 0.19,0.11,0.03";

// That background as 8-bit.
bool isBackground(const glm::u8vec4& px) {
  return std::abs(px.r - 48) <= 2 && std::abs(px.g - 28) <= 2 && std::abs(px.b - 8) <= 2;
}

}  // namespace

TEST(CliRender, HelpExitsZeroAndListsCommands) {
  const auto r = runMarble("--help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* cmd : {"render", "view", "texture", "presets"}) EXPECT_NE(r.output.find(cmd), std::string::npos) << cmd;
  EXPECT_EQ(runMarble("render --help").exitCode, 0);
}

TEST(CliRender, BadUsageExitsTwo) {
  EXPECT_EQ(runMarble("").exitCode, 2);
  EXPECT_EQ(runMarble("frobnicate").exitCode, 2);
  EXPECT_EQ(runMarble("render").exitCode, 2);  // -o is required
  EXPECT_EQ(runMarble("render -o x.png --width 0").exitCode, 2);
  const auto r = runMarble("render -o /tmp/x.png --mode sparkly");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("unknown render mode"), std::string::npos) << r.output;
}

TEST(CliRender, DefaultSceneRendersCentredObject) {
  const auto dir = tempDir("render-default");
  const auto out = dir / "default.png";
  const auto r = runMarble("render -o " + out.string() + " --width 160 --height 120" + kFlatStage);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(out);
  ASSERT_EQ(img.width, 160);
  ASSERT_EQ(img.height, 120);
  int covered = 0;
  double cx = 0, cy = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (!isBackground(img.at(x, y))) {
        ++covered;
        cx += x;
        cy += y;
      }
  EXPECT_GT(covered, img.width * img.height / 10) << "the object should cover a plausible part of the frame";
  EXPECT_NEAR(cx / covered, 80.0, 16.0) << "and be centred";
  EXPECT_NEAR(cy / covered, 60.0, 12.0);
  EXPECT_TRUE(isBackground(img.at(1, 1))) << "corners show the background";
  EXPECT_TRUE(isBackground(img.at(158, 118)));
  // No temporary left beside the output.
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
}

// Issue 15: the stone as a Blender user gives it renders without a warning; giving both forms
// and a crease angle out of [0, 180] is a usage error (exit 2).
TEST(CliRender, PrincipledMaterialRendersWithoutWarnings) {
  const auto dir = tempDir("render-principled");
  const auto scene = dir / "scene.json";
  std::ofstream(scene) << R"({"mesh": "builtin:sphere", "material": {"base_color": [0.87, 0.85, 0.8],
    "subsurface_radius_mm": [17, 12, 8], "ior": 1.5, "roughness": 0.15}, "render": {"environment": "none"}})";
  const auto r = runMarble("render " + scene.string() + " -o " + (dir / "p.png").string() + " --width 64 --height 64");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  const auto badCrease = runMarble("render " + scene.string() + " -o " + (dir / "q.png").string() +
                              " --width 8 --height 8 --crease-angle 181");
  EXPECT_EQ(badCrease.exitCode, 2) << badCrease.output;
}

TEST(CliRender, SupersampleRendersLargerAndWritesTheRequestedSize) {
  const auto dir = tempDir("render-supersample");
  const auto png = dir / "ss.png", exr = dir / "ss.exr";
  const auto r = runMarble("render -o " + png.string() + " --hdr " + exr.string() + " --width 48 --height 36 --supersample 3" + kFlatStage);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("48x36"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("supersampled 3x3"), std::string::npos) << r.output;
  const ImageRGBA8 img = readPng(png);
  EXPECT_EQ(img.width, 48);
  EXPECT_EQ(img.height, 36);
  const ImageRGBF hdr = readExr(exr);
  EXPECT_EQ(hdr.width, 48);
  EXPECT_EQ(hdr.height, 36);
  EXPECT_TRUE(isBackground(img.at(1, 1))) << "corners show the background";
  EXPECT_FALSE(isBackground(img.at(24, 18))) << "and the object is in the middle";
}

TEST(CliRender, SupersampleOutOfRangeOrTooLargeExitsTwo) {
  for (const char* n : {"0", "5", "two"}) {
    const auto r = runMarble(std::string("render -o /tmp/x.png --width 16 --height 16 --supersample ") + n);
    EXPECT_EQ(r.exitCode, 2) << n << ": " << r.output;
    EXPECT_NE(r.output.find("--supersample"), std::string::npos) << r.output;
  }
  // The size limit applies to what is rendered: 3 x 3000 = 9000 > 8192.
  const auto dir = tempDir("render-supersample-large");
  const auto r = runMarble("render -o " + (dir / "x.png").string() + " --width 3000 --height 20 --supersample 3");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--supersample: 3 times 3000x20 is 9000x60, above the limit of 8192"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(CliRender, AntialiasOption) {
  const auto dir = tempDir("render-antialias");
  const auto none = dir / "none.png", fxaa = dir / "fxaa.png";
  ASSERT_EQ(runMarble("render -o " + none.string() + " --width 64 --height 64 --antialias none").exitCode, 0);
  ASSERT_EQ(runMarble("render -o " + fxaa.string() + " --width 64 --height 64 --antialias fxaa").exitCode, 0);
  EXPECT_NE(readPng(none).pixels, readPng(fxaa).pixels) << "FXAA changes the silhouette's pixels";
  const auto bad = runMarble("render -o " + none.string() + " --width 16 --height 16 --antialias msaa");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--antialias: expected \"fxaa\" or \"none\", got \"msaa\""), std::string::npos) << bad.output;
}

TEST(CliRender, BadMeshFilesGiveOneLineAndExitTwo) {
  const auto dir = tempDir("render-bad");
  struct Case {
    std::string name, content, expect;
  };
  const std::vector<Case> cases = {
      {"empty.obj", "", "empty.obj"},
      {"garbage.obj", std::string("\x7f\x45\x4c\x46\x02\x01\x01\x00\xff\xfe", 10), "garbage.obj"},
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "line 4"},
      {"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4"},
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2"},
      {"nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "nofaces.obj"},
  };
  for (const auto& c : cases) {
    writeFile(dir / c.name, c.content);
    const auto r = runMarble("render " + (dir / c.name).string() + " -o " + (dir / "out.png").string());
    EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.name << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.name << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  }
  const auto missing = runMarble("render " + (dir / "missing.obj").string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("missing.obj"), std::string::npos);
  const auto directory = runMarble("render " + dir.string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(directory.exitCode, 2) << directory.output;
}

TEST(CliRender, BadSceneNamesFileAndField) {
  const auto dir = tempDir("render-scene");
  writeFile(dir / "s.json", R"({"camera": {"fov_y_deg": "wide"}})");
  auto r = runMarble("render " + (dir / "s.json").string() + " -o " + (dir / "o.png").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("s.json: camera.fov_y_deg: expected a number"), std::string::npos) << r.output;
  writeFile(dir / "u.json", R"({"mesh": "builtin:sphere", "colour": 1, "render": {"width": 32, "height": 32}})");
  r = runMarble("render " + (dir / "u.json").string() + " -o " + (dir / "o.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("warning: " + (dir / "u.json").string() + ": colour: unknown key"), std::string::npos) << r.output;
}

TEST(CliRender, EnvironmentMapLightsTheObjectAndABadOneExitsTwo) {
  const auto dir = tempDir("render-env");
  std::filesystem::create_directories(dir / "maps");
  std::filesystem::create_directories(dir / "scenes");
  writeHdrFile(dir / "maps" / "sky.hdr", syntheticSky(64));
  const std::string size = " --width 64 --height 64 --set roughness=0.1";
  auto r = runMarble("render builtin:sphere -o " + (dir / "studio.png").string() + size);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  r = runMarble("render builtin:sphere --environment-map " + (dir / "maps" / "sky.hdr").string() + " -o " +
                (dir / "map.png").string() + size);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 studio = readPng(dir / "studio.png"), map = readPng(dir / "map.png");
  int differ = 0;
  for (size_t i = 0; i < map.pixels.size(); ++i) differ += std::abs(int(map.pixels[i]) - int(studio.pixels[i])) > 8;
  EXPECT_GT(differ, 500) << "the map, not the studio, lights the sphere";
  // In a scene the path is relative to the scene's folder, like the mesh.
  writeFile(dir / "scenes" / "s.json", R"({"mesh": "builtin:sphere", "render": {"width": 64, "height": 64, "environment_map": "../maps/sky.hdr"}})");
  r = runMarble("render " + (dir / "scenes" / "s.json").string() + " -o " + (dir / "scene.png").string() + " --set roughness=0.1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readPng(dir / "scene.png").pixels, map.pixels);
  // A bad map: one line naming the file, exit 2, no picture.
  writeFile(dir / "bad.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n" + std::string(100, '\x01'));
  r = runMarble("render builtin:sphere --environment-map " + (dir / "bad.hdr").string() + " -o " + (dir / "bad.png").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find((dir / "bad.hdr").string() + ": "), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
  r = runMarble("render builtin:sphere --environment-map " + (dir / "none.hdr").string() + " -o " + (dir / "bad.png").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("none.hdr: file not found"), std::string::npos) << r.output;
}

TEST(CliRender, UnwritableOutputExitsTwo) {
  const auto r = runMarble("render -o /nonexistent-dir/x.png --width 16 --height 16");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/nonexistent-dir/x.png"), std::string::npos) << r.output;
}

TEST(CliView, WithoutDisplaySaysSoAndPointsAtRender) {
  const auto r = runMarble("view", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("marble render"), std::string::npos) << r.output;
}

TEST(CliView, UnderXvfbDrawsFramesAndSavesScreenshotWithMeshAndPanel) {
  const auto dir = tempDir("view");
  const auto shot = dir / "shot.png";
  const auto r = runMarble("view --frames 3 --width 640 --height 480 --screenshot " + shot.string() + kFlatStage,
                           "xvfb-run -a -s '-screen 0 1024x768x24'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(shot);
  ASSERT_EQ(img.width, 640);
  ASSERT_EQ(img.height, 480);
  // The mesh: the right half's centre (beside the panel) is not background; corners are.
  EXPECT_TRUE(isBackground(img.at(630, 470)));
  int object = 0, panel = 0;
  for (int y = 150; y < 330; ++y)
    for (int x = 420; x < 600; ++x)
      if (!isBackground(img.at(x, y))) ++object;
  EXPECT_GT(object, 1000) << "the mesh should be visible right of the panel";
  // The panel: ImGui's dark-blue title bar and grey-blue window at the top left.
  for (int y = 12; y < 60; ++y)
    for (int x = 12; x < 300; ++x) {
      const auto px = img.at(x, y);
      if (px.b > px.r + 15) ++panel;
    }
  EXPECT_GT(panel, 500) << "the ImGui panel should be drawn at the top left";
}

TEST(CliRender, ShaderFolderOverridesTheBuiltInShaders) {
  // MARBLE_SHADER_DIR: a file there replaces the built-in one of the same name (here the post
  // pass, painting the surface magenta); the others stay built in (the background is the
  // scene's, around the object).
  const auto dir = tempDir("shader-dir");
  std::filesystem::create_directories(dir / "shaders");
  writeFile(dir / "shaders" / "post.frag.glsl",
            "#version 450 core\nlayout(location = 0) out vec4 o_color;\nvoid main() { o_color = vec4(1, 0, 1, 1); }\n");
  const auto out = dir / "magenta.png";
  const auto r = runMarble("render -o " + out.string() + " --width 16 --height 16 --antialias none",
                           "MARBLE_SHADER_DIR=" + (dir / "shaders").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(out);
  EXPECT_NE(img.at(0, 0), glm::u8vec4(255, 0, 255, 255));
  EXPECT_EQ(img.at(0, 0).a, 255) << "the background is opaque (FXAA's luma stays in its input)";
  EXPECT_EQ(img.at(8, 8), glm::u8vec4(255, 0, 255, 255));
}
