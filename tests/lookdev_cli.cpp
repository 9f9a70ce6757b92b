// Look-dev from the command line (issue 19): the light, camera, size, exposure and stage flags
// change the picture as they say; a PNG carries its scene and re-renders to the same pixels;
// turntables write numbered frames (and a video when ffmpeg is installed); --quality final.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <glm/glm.hpp>

#include "cli_support.h"
#include "marble/core/image.h"
#include "marble/scene/scene_io.h"

using namespace marble;
using namespace marble::test;

namespace {

const std::string kSize = " --width 48 --height 48";

ImageRGBA8 render(const std::filesystem::path& dir, const std::string& name, const std::string& args) {
  const auto out = dir / name;
  const auto r = runMarble("render " + args + kSize + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return readPng(out);
}

double meanLuma(const ImageRGBA8& img) {
  double sum = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 4) sum += img.pixels[i] + img.pixels[i + 1] + img.pixels[i + 2];
  return sum / (3.0 * img.width * img.height);
}

bool samePixels(const ImageRGBA8& a, const ImageRGBA8& b) {
  return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

}  // namespace

TEST(CliLookdev, CameraAnglesAndPositionAgree) {
  const auto dir = tempDir("lookdev-camera");
  // Azimuth 0, elevation 0 at distance 4 is the point (0, 0, 4): the same view either way.
  const auto byAngles = render(dir, "a.png", "--camera 0,0,4");
  const auto byPosition = render(dir, "p.png", "--camera-position 0,0,4");
  EXPECT_TRUE(samePixels(byAngles, byPosition));
  const auto side = render(dir, "s.png", "--camera side");
  EXPECT_FALSE(samePixels(byAngles, side)) << "negative control: another camera, another picture";
}

TEST(CliLookdev, LightPresetsMoveTheLight) {
  const auto dir = tempDir("lookdev-light");
  const auto front = render(dir, "f.png", "--light front");
  const auto back = render(dir, "b.png", "--light back");
  EXPECT_FALSE(samePixels(front, back));
  // Lit from the camera's side the visible surface is brighter than lit from behind.
  EXPECT_GT(meanLuma(front), meanLuma(back));
  const auto pos = render(dir, "p.png", "--light-position 0,0,-5");
  EXPECT_FALSE(samePixels(pos, front));
}

TEST(CliLookdev, SizeMmIsMmPerUnitTimesTwo) {
  const auto dir = tempDir("lookdev-size");
  std::ofstream(dir / "s.json") << R"({"mesh": "builtin:torus", "mm_per_unit": 20})";
  const auto fromScene = render(dir, "j.png", (dir / "s.json").string());
  const auto fromFlag = render(dir, "f.png", "builtin:torus --size-mm 40");
  EXPECT_TRUE(samePixels(fromScene, fromFlag));
  // The flag overrides the scene file.
  const auto overridden = render(dir, "o.png", (dir / "s.json").string() + " --size-mm 2000");
  EXPECT_FALSE(samePixels(fromScene, overridden));
}

TEST(CliLookdev, ExposureAndBackground) {
  const auto dir = tempDir("lookdev-exposure");
  const auto base = render(dir, "0.png", "builtin:torus --background 0,0,0");
  const auto brighter = render(dir, "1.png", "builtin:torus --background 0,0,0 --exposure 1");
  EXPECT_GT(meanLuma(brighter), meanLuma(base) * 1.1);
  const auto blue = render(dir, "b.png", "builtin:torus --background 0,0,1");
  const auto corner = blue.at(0, 0);
  EXPECT_EQ(corner.r, 0);
  EXPECT_EQ(corner.g, 0);
  EXPECT_EQ(corner.b, 255);
}

TEST(CliLookdev, PngCarriesItsSceneAndReRendersToTheSamePixels) {
  const auto dir = tempDir("lookdev-png");
  const auto shot = render(dir, "shot.png", "builtin:torus --light side --size-mm 30 --exposure 0.5 --set seed=7");
  const auto text = readPngText(dir / "shot.png", kPngSceneKeyword);
  ASSERT_TRUE(text.has_value());
  EXPECT_NE(text->find("\"mm_per_unit\": 15.0"), std::string::npos) << *text;
  const auto r = runMarble("render " + (dir / "shot.png").string() + " -o " + (dir / "again.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(samePixels(shot, readPng(dir / "again.png")));
}

TEST(CliLookdev, QualityFinalSupersamplesWithoutFxaa) {
  const auto dir = tempDir("lookdev-final");
  const auto r = runMarble("render --quality final" + kSize + " -o " + (dir / "f.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("supersampled 3x3, final quality"), std::string::npos) << r.output;
  const auto same = render(dir, "s.png", "--supersample 3 --antialias none --subsurface-resolution full");
  EXPECT_TRUE(samePixels(readPng(dir / "f.png"), same)) << "final is exactly these three settings";
}

TEST(CliLookdev, TurntableWritesNumberedFramesOfAFullTurn) {
  const auto dir = tempDir("lookdev-turntable");
  const auto frames = dir / "frames";
  const auto r = runMarble("render builtin:torus --turntable 4" + kSize + " -o " + frames.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("ms per frame"), std::string::npos) << r.output;
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::filesystem::exists(frames / ("frame_000" + std::to_string(i) + ".png")));
  EXPECT_FALSE(std::filesystem::exists(frames / "frame_0004.png"));
  EXPECT_FALSE(samePixels(readPng(frames / "frame_0000.png"), readPng(frames / "frame_0001.png")));
  // The light turning leaves the object's silhouette where it is; the shading moves.
  const auto lightFrames = dir / "light";
  ASSERT_EQ(runMarble("render builtin:torus --turntable 2 --turntable-of light" + kSize + " -o " + lightFrames.string()).exitCode, 0);
  EXPECT_FALSE(samePixels(readPng(lightFrames / "frame_0000.png"), readPng(lightFrames / "frame_0001.png")));
}

TEST(CliLookdev, TurntableVideoWithFfmpeg) {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg is not installed (tools/deps.txt lists it)";
  const auto dir = tempDir("lookdev-video");
  for (const char* ext : {".mp4", ".webp"}) {
    const auto video = dir / (std::string("turn") + ext);
    const auto r = runMarble("render builtin:torus --turntable 3 --width 32 --height 32 -o " + (dir / "f").string() +
                             " --video " + video.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(video, std::ios::binary);
    std::string head(12, '\0');
    in.read(head.data(), 12);
    if (std::string(ext) == ".mp4") EXPECT_EQ(head.substr(4, 4), "ftyp");
    else EXPECT_EQ(head.substr(8, 4), "WEBP");
  }
}

namespace {
// The pixel where a world point appears in a square image of the default camera (Scene{}'s:
// at (0, 0.8, 4.2) looking at the origin, 40 degrees), top row first.
glm::ivec2 pixelOf(const glm::vec3& p, int size) {
  const glm::vec3 eye(0.0f, 0.8f, 4.2f);
  const glm::vec3 f = glm::normalize(-eye), r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0))), u = glm::cross(r, f);
  const glm::vec3 d = p - eye;
  const float t = std::tan(glm::radians(20.0f));
  const float x = glm::dot(d, r) / glm::dot(d, f) / t, y = glm::dot(d, u) / glm::dot(d, f) / t;
  return {static_cast<int>((x * 0.5f + 0.5f) * size), static_cast<int>((0.5f - y * 0.5f) * size)};
}
int luma(const glm::u8vec4& c) { return c.r + c.g + c.b; }
}  // namespace

TEST(CliLookdev, GroundReceivesTheObjectsShadow) {
  const auto dir = tempDir("lookdev-ground");
  const std::string sphere = "builtin:sphere --light top --background 0,0,0";
  const auto ground = render(dir, "g.png", sphere + " --ground on");
  // The unit sphere stands on y = -1; the light straight above shadows the floor within radius 1.
  const glm::ivec2 shadowed = pixelOf({0.0f, -1.0f, 0.8f}, 48), lit = pixelOf({1.8f, -1.0f, 0.8f}, 48);
  EXPECT_GT(luma(ground.at(lit.x, lit.y)), 30) << "the lit floor shows";
  EXPECT_LT(luma(ground.at(shadowed.x, shadowed.y)), luma(ground.at(lit.x, lit.y)) * 0.6) << "the shadow under the sphere";
  // Negative control: without the ground both points are the background.
  const auto flat = render(dir, "f.png", sphere);
  EXPECT_EQ(luma(flat.at(lit.x, lit.y)), 0);
  EXPECT_EQ(luma(flat.at(shadowed.x, shadowed.y)), 0);
}

TEST(CliLookdev, BackdropShowsTheEnvironmentBehindTheObject) {
  const auto dir = tempDir("lookdev-backdrop");
  const std::string args = "builtin:sphere --background 0,0,1";
  const auto plain = render(dir, "p.png", args);
  const auto backdrop = render(dir, "b.png", args + " --backdrop on --backdrop-blur 0.5");
  EXPECT_EQ(plain.at(2, 2), glm::u8vec4(0, 0, 255, 255));
  const auto c = backdrop.at(2, 2);
  EXPECT_LT(std::abs(int(c.r) - int(c.b)), 12) << "the studio's grey, not the blue background";
  // With no environment there is nothing to show: the background colour stays.
  const auto none = render(dir, "n.png", args + " --backdrop on --environment none");
  EXPECT_EQ(none.at(2, 2), glm::u8vec4(0, 0, 255, 255));
}
