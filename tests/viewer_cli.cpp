// The viewer end to end under Xvfb: it starts, draws frames, saves the window on request and
// exits cleanly; the picture shows the docked panel at the left and the object, whole and
// centred, in the view right of it. Bad input on the command line is one line and exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cli_support.h"
#include "hdr_support.h"
#include "marble/core/image.h"

namespace marble {
namespace {

using test::runMarble;
using test::tempDir;

// A virtual X server for one command. xvfb-run's own temporary folder is avoided (-f names the
// authority file in a folder of ours): its clean-up failed now and then when tests ran in
// parallel, turning a passing viewer run into exit code 5.
struct XauthorityFolder {
  test::TempDir dir{"xvfb"};
};
std::string xvfb() {
  static XauthorityFolder folder;
  static int runs = 0;
  const auto file = folder.dir / ("Xauthority-" + std::to_string(++runs));
  return "xvfb-run -a -f " + file.string() + " -s '-screen 0 1024x768x24'";
}

bool isBackground(const glm::u8vec4& px) {  // the default scene's background, as displayed
  return std::abs(px.r - 48) <= 3 && std::abs(px.g - 28) <= 3 && std::abs(px.b - 8) <= 3;
}

int lineCount(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n + (!s.empty() && s.back() != '\n');
}

TEST(ViewerCli, ABrokenShaderIsOneLineAndExitOne) {
  // Issue 7: a shader that fails to compile when the viewer starts: one line naming file and
  // line, exit code 1 (there is no last good shader yet to keep; `--dev` reloads keep it).
  const auto dir = tempDir("viewer-shader");
  std::filesystem::create_directories(dir / "shaders");
  std::ofstream(dir / "shaders" / "lighting.frag.glsl") << "#version 450 core\nvoid main() { nonsense; }\n";
  const auto r = runMarble("view --frames 2 --width 320 --height 240",
                           xvfb() + " env MARBLE_SHADER_DIR=" + (dir / "shaders").string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("marble view: " + (dir / "shaders" / "lighting.frag.glsl").string() + ":2: error"),
            std::string::npos)
      << r.output;
}

TEST(ViewerCli, DrawsThePanelLeftAndTheWholeObjectCentredBesideIt) {
  const auto dir = tempDir("viewer-shot");
  const auto shot = dir / "shot.png";
  // The showcase's stage off and the paper's brown behind it, so that the object can be found.
  const auto r = runMarble("view --frames 4 --width 800 --height 500 --screenshot " + shot.string() +
                               " --ground off --backdrop off --background 0.19,0.11,0.03",
                           xvfb());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const ImageRGBA8 img = readPng(shot);
  ASSERT_EQ(img.width, 800);
  ASSERT_EQ(img.height, 500);

  // The panel: a column at the left, full height, ImGui's dark window with blue-ish headers.
  int blue = 0, dark = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < 300; ++x) {
      const auto px = img.at(x, y);
      if (px.b > px.r + 20) ++blue;
      if (px.r < 40 && px.g < 40 && px.b < 40) ++dark;
    }
  EXPECT_GT(blue, 3000) << "headers, sliders and buttons of the panel";
  EXPECT_GT(dark, 20000) << "the panel's window background";
  EXPECT_FALSE(isBackground(img.at(5, img.height - 5))) << "the panel reaches the bottom of the window";

  // The view: right of the panel; the object's pixels are all there and centred in it.
  int left = img.width;
  for (int x = 0; x < img.width; ++x)
    if (isBackground(img.at(x, img.height / 2)) || isBackground(img.at(x, 3))) {
      left = x;
      break;
    }
  ASSERT_LT(left, img.width / 2) << "the 3D view starts right of the panel";
  long covered = 0;
  double cx = 0, cy = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = left; x < img.width; ++x)
      if (!isBackground(img.at(x, y))) {
        ++covered;
        cx += x;
        cy += y;
      }
  ASSERT_GT(covered, 5000) << "the mesh is drawn";
  EXPECT_NEAR(cx / covered, (left + img.width) / 2.0, (img.width - left) * 0.12) << "centred in the view";
  EXPECT_NEAR(cy / covered, img.height / 2.0, img.height * 0.12);
  for (int y = 0; y < img.height; ++y) {  // nothing of the object touches the view's borders
    EXPECT_TRUE(isBackground(img.at(left + 2, y))) << "y " << y;
    EXPECT_TRUE(isBackground(img.at(img.width - 2, y))) << "y " << y;
    if (!isBackground(img.at(left + 2, y)) || !isBackground(img.at(img.width - 2, y))) break;
  }
}

TEST(ViewerCli, OpensAMeshFileWithAPreset) {
  // The screenshot script and the tests share --frames/--screenshot; other inputs work too.
  const auto dir = tempDir("viewer-mesh");
  const auto shot = dir / "cube.png";
  const auto r = runMarble("view " + std::string(MARBLE_TEST_FIXTURES) + "/mesh/cube_flat.obj --preset carrara --frames 2 "
                               "--width 400 --height 300 --screenshot " + shot.string(), xvfb());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readPng(shot).width, 400);
}

// --turntable starts the panel's turntable: the object turns between frames, so two runs with a
// different number of frames end on different pictures; off, they are the same.
TEST(ViewerCli, TurntableTurnsTheObjectBetweenFrames) {
  const auto dir = tempDir("viewer-turntable");
  auto shot = [&](const std::string& name, const std::string& args) {
    const auto png = dir / name;
    const auto r = runMarble("view --frames 12 --width 400 --height 300 --screenshot " + png.string() + " " + args, xvfb());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readPng(png);
  };
  const ImageRGBA8 still = shot("still.png", "");
  const ImageRGBA8 turned = shot("turned.png", "--turntable object --turntable-speed 900");
  int differing = 0;
  for (size_t i = 0; i < still.pixels.size(); i += 4) differing += still.pixels[i] != turned.pixels[i];
  EXPECT_GT(differing, 500) << "the object turned";
}

TEST(ViewerCli, InteractionDetailSettingIsCheckedAndRuns) {
  const auto bad = runMarble("view --frames 1 --interaction-detail sometimes", xvfb());
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_EQ(lineCount(bad.output), 1) << bad.output;
  EXPECT_NE(bad.output.find("--interaction-detail"), std::string::npos) << bad.output;
  const auto on = runMarble("view --frames 4 --width 320 --height 240 --interaction-detail on --turntable object", xvfb());
  EXPECT_EQ(on.exitCode, 0) << on.output;
  const auto badScale = runMarble("view --frames 1 --interaction-resolution 2", xvfb());
  EXPECT_EQ(badScale.exitCode, 2) << badScale.output;
  EXPECT_EQ(lineCount(badScale.output), 1) << badScale.output;
  EXPECT_NE(badScale.output.find("--interaction-resolution"), std::string::npos) << badScale.output;
  const auto light = runMarble("view --frames 4 --width 320 --height 240 --interaction-resolution 0.25 --turntable light", xvfb());
  EXPECT_EQ(light.exitCode, 0) << light.output;
  const auto badMaps = runMarble("view --frames 1 --interaction-light-maps half", xvfb());
  EXPECT_EQ(badMaps.exitCode, 2) << badMaps.output;
  EXPECT_NE(badMaps.output.find("--interaction-light-maps"), std::string::npos) << badMaps.output;
  const auto mapsOff = runMarble("view --frames 4 --width 320 --height 240 --interaction-light-maps off --turntable object", xvfb());
  EXPECT_EQ(mapsOff.exitCode, 0) << mapsOff.output;
}

TEST(ViewerCli, BadMeshOnTheCommandLineIsOneLineAndExitTwo) {
  const auto r = runMarble("view /nonexistent/thing.obj --frames 1", xvfb());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/thing.obj"), std::string::npos) << r.output;
}

TEST(ViewerCli, BadSceneFileIsOneLineAndExitTwo) {
  const auto dir = tempDir("viewer-badscene");
  const auto scene = dir / "bad.json";
  { std::ofstream(scene) << "{\"camera\": {\"fov_y_deg\": 500}}"; }
  const auto r = runMarble("view " + scene.string() + " --frames 1", xvfb());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("camera.fov_y_deg"), std::string::npos) << r.output;
}

TEST(ViewerCli, OpensWithAnEnvironmentMapAndABadOneIsOneLineAndExitTwo) {
  const auto dir = tempDir("viewer-env");
  test::writeHdrFile(dir / "sky.hdr", test::syntheticSky(64));
  { std::ofstream(dir / "bad.hdr") << "not an image"; }
  const auto shot = dir / "env.png";
  auto r = runMarble("view builtin:sphere --environment-map " + (dir / "sky.hdr").string() +
                         " --frames 2 --width 400 --height 300 --screenshot " + shot.string(), xvfb());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readPng(shot).width, 400);
  r = runMarble("view --environment-map " + (dir / "bad.hdr").string() + " --frames 1", xvfb());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_EQ(lineCount(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("bad.hdr: not a Radiance .hdr file"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace marble
