// Saving a whole scene from the viewer (src/marble/scene/scene_io.h) and reading it back with
// loadScene gives the same scene, bit for bit; the write is atomic.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/scene/material_io.h"
#include "marble/scene/scene_io.h"

namespace marble {
namespace {

std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("marble-viewer-io-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Scene unusualScene() {
  Scene s;
  s.mesh = "builtin:sphere";
  s.up = UpAxis::NegZ;
  s.camera.position = {0.1f, 1.0f / 3.0f, 5.5f};
  s.camera.target = {0.01f, -0.2f, 0.3f};
  s.camera.fov_y_deg = 33.3f;
  s.light.type = LightType::Directional;
  s.light.position = {-2.0f, 4.1f, 0.7f};
  s.light.color = {1.0f, 0.9f, 0.81f};
  s.light.intensity = 1.7f;
  s.material = loadPreset("calacatta");
  s.material.turb_power = 7.123456f;
  s.material.vein_color = {0.1f, 0.2f, 0.3f};
  s.material.order = ShadingOrder::ReflectanceFirst;
  s.material.seed = 4000000000u;
  s.render.width = 640;
  s.render.height = 360;
  s.render.background = {0.05f, 0.06f, 0.07f};
  s.render.mode = RenderMode::OrenNayar;
  s.render.antialias = Antialias::None;  // not the default
  return s;
}

void expectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.camera.position, b.camera.position);
  EXPECT_EQ(a.camera.target, b.camera.target);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fov_y_deg, b.camera.fov_y_deg);
  EXPECT_EQ(a.light.type, b.light.type);
  EXPECT_EQ(a.light.position, b.light.position);
  EXPECT_EQ(a.light.color, b.light.color);
  EXPECT_EQ(a.light.intensity, b.light.intensity);
  EXPECT_EQ(materialToJson(a.material), materialToJson(b.material));
  EXPECT_EQ(a.render.width, b.render.width);
  EXPECT_EQ(a.render.height, b.render.height);
  EXPECT_EQ(a.render.background, b.render.background);
  EXPECT_EQ(a.render.mode, b.render.mode);
  EXPECT_EQ(a.render.antialias, b.render.antialias);
}

TEST(ViewerSceneIo, SaveThenLoadGivesTheSameScene) {
  const auto dir = scratch("roundtrip");
  const Scene original = unusualScene();
  saveScene(dir / "scene.json", original);
  std::vector<std::string> warnings;
  const Scene loaded = loadScene(dir / "scene.json", warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(loaded.mesh, original.mesh);
  expectSameScene(loaded, original);
  std::filesystem::remove_all(dir);
}

TEST(ViewerSceneIo, MeshPathIsRelativeToTheSceneAndResolvesBack) {
  const auto dir = scratch("relative");
  std::filesystem::create_directories(dir / "meshes");
  std::filesystem::create_directories(dir / "scenes");
  Scene original = unusualScene();
  original.mesh = (dir / "meshes" / "thing.obj").string();
  saveScene(dir / "scenes" / "a.json", original);
  EXPECT_NE(readAll(dir / "scenes" / "a.json").find("\"../meshes/thing.obj\""), std::string::npos);
  std::vector<std::string> warnings;
  const Scene loaded = loadScene(dir / "scenes" / "a.json", warnings);
  EXPECT_EQ(std::filesystem::path(loaded.mesh).lexically_normal(), std::filesystem::path(original.mesh).lexically_normal());
  std::filesystem::remove_all(dir);
}

TEST(ViewerSceneIo, MaterialPresetRoundTripsExactly) {
  const auto dir = scratch("preset");
  Material m = unusualScene().material;
  m.name = "mine";
  m.sigma_t = {0.123456789f, 2.5f, 1e-3f};
  saveMaterial(dir / "mine.json", m);
  std::vector<std::string> warnings;
  const Material back = loadPreset((dir / "mine.json").string(), &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(materialToJson(back), materialToJson(m));
  std::filesystem::remove_all(dir);
}

TEST(ViewerSceneIo, AnInterruptedSaveLeavesTheOldFileIntact) {
  const auto dir = scratch("interrupted");
  const auto path = dir / "scene.json";
  saveScene(path, Scene{});
  const std::string before = readAll(path);
  setAtomicWriteFaultHookForTesting([] { throw std::runtime_error("simulated crash mid-write"); });
  EXPECT_ANY_THROW(saveScene(path, unusualScene()));
  setAtomicWriteFaultHookForTesting(nullptr);
  EXPECT_EQ(readAll(path), before);
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "no temporary left behind";
  std::filesystem::remove_all(dir);
}

TEST(ViewerSceneIo, AntialiasIsReadWrittenAndValidated) {
  const auto dir = scratch("antialias");
  std::vector<std::string> warnings;
  std::ofstream(dir / "default.json") << R"({"render": {"width": 32}})";
  EXPECT_EQ(loadScene(dir / "default.json", warnings).render.antialias, Antialias::Fxaa) << "FXAA is the default";
  std::ofstream(dir / "none.json") << R"({"render": {"antialias": "none"}})";
  EXPECT_EQ(loadScene(dir / "none.json", warnings).render.antialias, Antialias::None);
  std::ofstream(dir / "fxaa.json") << R"({"render": {"antialias": "fxaa"}})";
  EXPECT_EQ(loadScene(dir / "fxaa.json", warnings).render.antialias, Antialias::Fxaa);
  EXPECT_TRUE(warnings.empty()) << warnings.front();

  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"({"render": {"antialias": "msaa"}})", "render.antialias: expected \"fxaa\" or \"none\", got \"msaa\""},
      {R"({"render": {"antialias": "FXAA"}})", "render.antialias: expected \"fxaa\" or \"none\", got \"FXAA\""},
      {R"({"render": {"antialias": true}})", "render.antialias: expected a string, got boolean true"},
  };
  for (const auto& [text, message] : bad) {
    std::ofstream(dir / "bad.json") << text;
    try {
      loadScene(dir / "bad.json", warnings);
      ADD_FAILURE() << text << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.json: " + message), std::string::npos) << e.what();
    }
  }

  Scene none;
  none.render.antialias = Antialias::None;
  EXPECT_NE(sceneToJsonText(none, "s.json").find("\"antialias\": \"none\""), std::string::npos);
  EXPECT_NE(sceneToJsonText(Scene{}, "s.json").find("\"antialias\": \"fxaa\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ViewerSceneIo, KeysComeInAReadableOrder) {
  const std::string text = sceneToJsonText(Scene{}, "scene.json");
  const auto mesh = text.find("\"mesh\""), camera = text.find("\"camera\""), material = text.find("\"material\"");
  const auto name = text.find("\"name\""), oren = text.find("\"oren_nayar_sigma\"");
  ASSERT_NE(mesh, std::string::npos);
  EXPECT_LT(mesh, camera);
  EXPECT_LT(camera, material);
  EXPECT_LT(material, name);
  EXPECT_LT(name, oren);
}

}  // namespace
}  // namespace marble
