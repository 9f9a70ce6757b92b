// The scene's environment fields (render.environment, environment_map, environment_rotation_deg):
// read, validated with the file and the field named, resolved against the scene's folder, and
// written back by the scene writer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "marble/core/error.h"
#include "marble/scene/scene_io.h"

using namespace marble;

namespace {

namespace fs = std::filesystem;

class SceneEnvironment : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("marble-scene-env-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "scenes");
  }
  void TearDown() override { fs::remove_all(dir_); }

  Scene load(const std::string& json, std::vector<std::string>* warningsOut = nullptr) {
    const fs::path p = dir_ / "scenes" / "s.json";
    std::ofstream(p) << json;
    std::vector<std::string> warnings;
    Scene s = loadScene(p, warnings);
    if (warningsOut) *warningsOut = warnings;
    return s;
  }
  void expectError(const std::string& json, const std::string& expected) {
    try {
      load(json);
      ADD_FAILURE() << json << ": loaded without an error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << "expected: " << expected << "\n     got: " << e.what();
    }
  }

  fs::path dir_;
};

}  // namespace

TEST_F(SceneEnvironment, DefaultsAreTheStudio) {
  const Scene s = load("{}");
  EXPECT_EQ(s.render.environment, Environment::Studio);
  EXPECT_TRUE(s.render.environment_map.empty());
  EXPECT_EQ(s.render.environment_rotation_deg, 0.0f);
}

TEST_F(SceneEnvironment, MapPathIsRelativeToTheSceneAndImpliesMap) {
  std::vector<std::string> warnings;
  const Scene s = load(R"({"render": {"environment_map": "../maps/sky.hdr", "environment_rotation_deg": -90}})", &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(s.render.environment, Environment::Map);
  EXPECT_EQ(fs::path(s.render.environment_map), (dir_ / "maps" / "sky.hdr").lexically_normal());
  EXPECT_EQ(s.render.environment_rotation_deg, -90.0f);
  // Naming a map with another environment keeps the path for later and uses that environment.
  const Scene studio = load(R"({"render": {"environment": "studio", "environment_map": "sky.hdr"}})");
  EXPECT_EQ(studio.render.environment, Environment::Studio);
  EXPECT_EQ(fs::path(studio.render.environment_map), dir_ / "scenes" / "sky.hdr");
  EXPECT_EQ(load(R"({"render": {"environment": "none"}})").render.environment, Environment::None);
}

TEST_F(SceneEnvironment, BadValuesNameTheField) {
  expectError(R"({"render": {"environment": "sky"}})", "s.json: render.environment: expected \"studio\", \"none\" or \"map\", got \"sky\"");
  expectError(R"({"render": {"environment": "map"}})",
              "s.json: render.environment: \"map\" needs render.environment_map (an equirectangular .hdr file)");
  expectError(R"({"render": {"environment_map": ""}})", "s.json: render.environment_map: must not be empty");
  expectError(R"({"render": {"environment_map": 7}})", "s.json: render.environment_map: expected a string, got number 7");
  expectError(R"({"render": {"environment_map": "a.hdr", "environment_rotation_deg": 400}})",
              "s.json: render.environment_rotation_deg: expected a number in [-360, 360], got 400");
}

TEST_F(SceneEnvironment, TheWriterWritesThemAndTheyReadBack) {
  Scene s;
  s.render.environment = Environment::Map;
  s.render.environment_map = (dir_ / "maps" / "sky.hdr").string();
  s.render.environment_intensity = 1.25f;
  s.render.environment_rotation_deg = 37.5f;
  s.render.exposure = -0.5f;
  const fs::path path = dir_ / "scenes" / "saved.json";
  saveScene(path, s);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"environment_map\": \"../maps/sky.hdr\""), std::string::npos) << text;
  std::vector<std::string> warnings;
  const Scene back = loadScene(path, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(back.render.environment, Environment::Map);
  EXPECT_EQ(fs::path(back.render.environment_map).lexically_normal(), fs::path(s.render.environment_map).lexically_normal());
  EXPECT_EQ(back.render.environment_intensity, 1.25f);
  EXPECT_EQ(back.render.environment_rotation_deg, 37.5f);
  EXPECT_EQ(back.render.exposure, -0.5f);
  // Without a map the key is left out, and "none" survives.
  Scene none;
  none.render.environment = Environment::None;
  const std::string noneText = sceneToJsonText(none, path);
  EXPECT_EQ(noneText.find("environment_map"), std::string::npos);
  saveScene(path, none);
  EXPECT_EQ(loadScene(path, warnings).render.environment, Environment::None);
}
