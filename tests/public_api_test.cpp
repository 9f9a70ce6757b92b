// The public interface marble/marble.h (docs/embedding.md) without GL: loading, the bake and
// export through it, and its errors (one line, the public InputError, nothing written). The GL
// half (StoneRenderer into the caller's framebuffer) runs in the install_example test, against
// the installed package.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "marble/marble.h"

namespace fs = std::filesystem;
using marble::api::BakeSettings;
using marble::api::InputError;
using marble::api::Stone;

namespace {
fs::path freshDir(const char* name) {
  const fs::path dir = fs::temp_directory_path() / (std::string("marble-api-") + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
}  // namespace

TEST(PublicApi, BakesAndExportsWhatTheCommandsWrite) {
  const fs::path dir = freshDir("bake");
  const Stone stone({.input = "builtin:cube", .preset = "nero-marquina", .sets = {"vein_sharpness=2"}, .up = ""});
  EXPECT_EQ(stone.triangleCount(), 12u);
  EXPECT_NE(stone.designJson().find("\"vein_sharpness\": 2"), std::string::npos);
  int calls = 0;
  BakeSettings s;
  s.size = 32;
  s.progress = [&](double, const char*) { return ++calls > 0; };
  const auto baked = marble::api::bakeTextureSet(stone, dir / "set", s);
  EXPECT_EQ(baked.size, 32);
  EXPECT_TRUE(baked.unwrapped);  // the built-in cube has no texture coordinates
  EXPECT_GT(baked.charts, 0);
  EXPECT_GT(calls, 0);
  for (const char* f : {"base_color.png", "metallic_roughness.png", "thickness.png", "material.json"}) EXPECT_TRUE(fs::exists(dir / "set" / f)) << f;
  marble::api::exportGltf(stone, dir / "cube.glb", {.size = 32, .supersample = 1, .uvFrom = "auto", .progress = {}});
  EXPECT_TRUE(fs::exists(dir / "cube.glb"));
  fs::remove_all(dir);
}

TEST(PublicApi, BadInputIsThePublicErrorAndWritesNothing) {
  const fs::path dir = freshDir("bad");
  EXPECT_THROW(Stone({.input = (dir / "missing.obj").string(), .preset = "", .sets = {}, .up = ""}), InputError);
  EXPECT_THROW(Stone({.input = "builtin:cube", .preset = "no-such-preset", .sets = {}, .up = ""}), InputError);
  EXPECT_THROW(Stone({.input = "builtin:cube", .preset = "", .sets = {"roughness"}, .up = ""}), InputError);
  EXPECT_THROW(Stone({.input = "builtin:cube", .preset = "", .sets = {}, .up = "w"}), InputError);
  const Stone stone({.input = "builtin:cube", .preset = "", .sets = {}, .up = ""});
  try {
    marble::api::bakeTextureSet(stone, dir / "set", {.size = 4, .supersample = 1, .uvFrom = "auto", .progress = {}});
    ADD_FAILURE() << "no error for size 4";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--size"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_THROW(marble::api::bakeTextureSet(stone, dir / "set", {.size = 32, .supersample = 1, .uvFrom = "maybe", .progress = {}}),
               InputError);
  EXPECT_THROW(marble::api::exportGltf(stone, dir / "cube.fbx"), InputError);
  // A cancelled bake is not bad input, and writes nothing either.
  EXPECT_THROW(marble::api::bakeTextureSet(stone, dir / "set",
                                           {.size = 64, .supersample = 1, .uvFrom = "auto", .progress = [](double, const char*) { return false; }}),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "set"));
  EXPECT_FALSE(fs::exists(dir / "cube.fbx"));
  fs::remove_all(dir);
}
