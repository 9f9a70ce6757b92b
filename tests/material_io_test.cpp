// Materials as JSON: presets, overrides, --set, validation, round trips.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include <unistd.h>

#include "error_text.h"
#include "temp_dir.h"
#include "marble/core/error.h"
#include "marble/scene/embedded_presets.h"
#include "marble/scene/material_io.h"
#include "marble/scene/material_params.h"

namespace marble {
namespace {

using json = nlohmann::json;
using marble::test::errorOf;

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Every parameter (from their descriptions: none can be left out), floats bit for bit.
void expectSame(const Material& a, const Material& b) {
  for (const auto& p : materialParams()) {
    const ParamValue va = p.get(a), vb = p.get(b);
    if (const auto* f = std::get_if<float>(&va)) {
      EXPECT_EQ(bits(*f), bits(std::get<float>(vb))) << p.key;
    } else if (const auto* c = std::get_if<glm::vec3>(&va)) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(bits((*c)[k]), bits(std::get<glm::vec3>(vb)[k])) << p.key << "[" << k << "]";
    } else {
      EXPECT_EQ(va, vb) << p.key;
    }
  }
  EXPECT_EQ(a, b);
}

TEST(MaterialIoTest, TheSixPresetsExistAndLoad) {
  std::set<std::string> names;
  for (const auto& p : builtinPresets()) {
    names.insert(p.name);
    EXPECT_FALSE(p.description.empty()) << p.name;
    std::vector<std::string> warnings;
    const Material m = loadPreset(p.name, &warnings);
    EXPECT_TRUE(warnings.empty()) << p.name << ": " << (warnings.empty() ? "" : warnings[0]);
    EXPECT_EQ(m.name, p.name);
    EXPECT_EQ(m.description, p.description);
  }
  for (const char* want : {"paper", "carrara", "calacatta", "nero-marquina", "verde-alpi", "rosso-levanto"})
    EXPECT_TRUE(names.count(want)) << want;
}

// Issue 14: the built-in material, which `marble --mode paper` renders without a preset, is the
// paper's (presets/paper.json), not a near copy with other colours and another Schlick cosine.
TEST(MaterialIoTest, DefaultIsThePaperPreset) {
  expectSame(Material{}, loadPreset("paper"));
  EXPECT_NE(Material{}, loadPreset("paper-program"));  // negative control
}

TEST(MaterialIoTest, EveryPresetFileSpellsOutEveryKey) {
  const auto keys = materialKeys();
  const std::set<std::string> keySet(keys.begin(), keys.end());
  EXPECT_EQ(keySet.size(), keys.size());
  for (const auto& [file, text] : embeddedPresets()) {
    const json j = json::parse(text);
    std::set<std::string> present;
    for (auto it = j.begin(); it != j.end(); ++it) present.insert(it.key());
    EXPECT_EQ(present, keySet) << file;
    EXPECT_EQ(j["name"].get<std::string>() + ".json", file);
  }
  // materialToJson writes exactly the documented keys.
  std::set<std::string> written;
  const json j = materialToJson(Material{});
  for (auto it = j.begin(); it != j.end(); ++it) written.insert(it.key());
  EXPECT_EQ(written, keySet);
}

TEST(MaterialIoTest, JsonRoundTripIsExact) {
  std::vector<Material> materials;
  for (const auto& p : builtinPresets()) materials.push_back(loadPreset(p.name));
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  for (int i = 0; i < 50; ++i) {
    Material m;
    m.seed = rng();
    m.resolution = 8 + static_cast<int>(rng() % 4000);
    m.turb_size = 1.0f + u01(rng) * 7.0f;
    m.x_period = (u01(rng) - 0.5f) * 100.0f;
    m.y_period = u01(rng) * 1e-3f;
    m.turb_power = u01(rng) * 20.0f;
    m.pattern_scale = 0.01f + u01(rng);
    m.base_color = {u01(rng), u01(rng), u01(rng)};
    m.sigma_t = {u01(rng) * 10.0f, 0.0f, 1.0f / 3.0f};
    m.k_schlick = u01(rng);
    m.basis = NoiseBasis::Perlin;
    m.mapping = PatternMapping::Triplanar;
    m.order = ShadingOrder::ReflectanceFirst;
    m.schlick_cos = SchlickCosine::HdotN;
    m.name = "random \"" + std::to_string(i) + "\"";
    materials.push_back(m);
  }
  const marble::test::TempDir dir("material");
  for (const Material& m : materials) {
    Material back;  // defaults differ from m in most fields
    std::vector<std::string> warnings;
    applyMaterialJson(back, materialToJson(m), "rt.json", "", warnings);
    EXPECT_TRUE(warnings.empty());
    expectSame(back, m);
    // Through a file too (text, not just the in-memory JSON).
    saveMaterial(dir / "m.json", m);
    expectSame(loadPreset((dir / "m.json").string()), m);
  }
}

TEST(MaterialIoTest, PresetThenOverrides) {
  Material m;
  std::vector<std::string> warnings;
  applyMaterialJson(m, json::parse(R"({"preset": "calacatta", "seed": 5, "mapping": "planar"})"), "scene.json",
                    "material.", warnings);
  const Material cal = loadPreset("calacatta");
  EXPECT_EQ(m.seed, 5u);
  EXPECT_EQ(m.mapping, PatternMapping::Planar);
  EXPECT_EQ(m.base_color, cal.base_color);
  EXPECT_EQ(m.vein_color, cal.vein_color);
  EXPECT_EQ(m.name, "calacatta");
  EXPECT_TRUE(warnings.empty());
}

TEST(MaterialIoTest, BadValuesNameTheFileAndTheKey) {
  auto bad = [](const char* text) {
    return errorOf([&] {
      Material m;
      std::vector<std::string> w;
      applyMaterialJson(m, json::parse(text), "scene.json", "material.", w);
    });
  };
  auto starts = [](const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; };
  EXPECT_PRED2(starts, bad(R"({"turb_power": -1})"), "scene.json: material.turb_power: expected a number in [0, 1000], got -1");
  EXPECT_PRED2(starts, bad(R"({"turb_power": "lots"})"), "scene.json: material.turb_power: expected a number");
  EXPECT_PRED2(starts, bad(R"({"seed": -3})"), "scene.json: material.seed: expected a whole number");
  EXPECT_PRED2(starts, bad(R"({"seed": 1.5})"), "scene.json: material.seed: expected a whole number");
  EXPECT_PRED2(starts, bad(R"({"resolution": 4})"), "scene.json: material.resolution: expected a whole number in [8, 4096], got 4");
  EXPECT_PRED2(starts, bad(R"({"resolution": true})"), "scene.json: material.resolution: expected a whole number");
  EXPECT_PRED2(starts, bad(R"({"base_color": [1, 0.5]})"), "scene.json: material.base_color: expected an array of 3 numbers");
  EXPECT_PRED2(starts, bad(R"({"base_color": [1, 0.5, 2]})"), "scene.json: material.base_color: expected an array of 3 numbers in [0, 1]");
  EXPECT_PRED2(starts, bad(R"({"sigma_t": [1, -0.5, 2]})"), "scene.json: material.sigma_t: expected");
  EXPECT_PRED2(starts, bad(R"({"k_schlick": 1.5})"), "scene.json: material.k_schlick: expected a number in [0, 1]");
  EXPECT_PRED2(starts, bad(R"({"mapping": "cubic"})"), "scene.json: material.mapping: expected one of \"planar\", \"triplanar\", \"solid\"");
  EXPECT_PRED2(starts, bad(R"({"basis": 1})"), "scene.json: material.basis: expected one of");
  EXPECT_PRED2(starts, bad(R"({"turb_size": 0.5})"), "scene.json: material.turb_size: expected a number in [1, 4096]");
  EXPECT_PRED2(starts, bad(R"({"resolution": 16, "turb_size": 32})"), "scene.json: material.turb_size: expected a number in [1, resolution = 16]");
  EXPECT_PRED2(starts, bad(R"({"preset": "granite"})"), "scene.json: material.preset: granite: not a built-in preset");
  EXPECT_PRED2(starts, bad(R"({"preset": 3})"), "scene.json: material.preset: expected a preset name or path");
  EXPECT_PRED2(starts, bad(R"({"name": 3})"), "scene.json: material.name: expected a string");
}

TEST(MaterialIoTest, UnknownKeysAreWarnedNotFatal) {
  Material m;
  std::vector<std::string> warnings;
  applyMaterialJson(m, json::parse(R"({"vein_colour": [1, 0, 0], "seed": 4})"), "scene.json", "material.", warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "scene.json: material.vein_colour: unknown key 'vein_colour' (ignored)");
  EXPECT_EQ(m.seed, 4u);
}

TEST(MaterialIoTest, PresetFilesOnDisk) {
  const marble::test::TempDir dir("preset");
  {
    std::ofstream(dir / "mine.json") << R"({"preset": "carrara", "turb_power": 2.5, "extra": 1})";
    std::ofstream(dir / "broken.json") << R"({"turb_power": 2.5,)";
    std::ofstream(dir / "bad.json") << R"({"vein_sharpness": 0})";
  }
  std::vector<std::string> warnings;
  const Material m = loadPreset((dir / "mine.json").string(), &warnings);
  EXPECT_EQ(m.turb_power, 2.5f);
  EXPECT_EQ(m.base_color, loadPreset("carrara").base_color);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("unknown key 'extra'"), std::string::npos);
  const std::string broken = errorOf([&] { loadPreset((dir / "broken.json").string()); });
  EXPECT_EQ(broken.rfind((dir / "broken.json").string() + ": invalid JSON", 0), 0u) << broken;
  const std::string badValue = errorOf([&] { loadPreset((dir / "bad.json").string()); });
  EXPECT_EQ(badValue.rfind((dir / "bad.json").string() + ": vein_sharpness: expected a number in [0.05, 20], got 0", 0), 0u)
      << badValue;
  EXPECT_NE(errorOf([&] { loadPreset((dir / "missing.json").string()); }).find("no such file"), std::string::npos);
  EXPECT_NE(errorOf([] { loadPreset("granite"); }).find("not a built-in preset"), std::string::npos);
}

TEST(MaterialIoTest, SetKeyParsesNumbersColoursAndNames) {
  Material m;
  setMaterialKey(m, "turb_power", "7.25");
  setMaterialKey(m, "seed", "123");
  setMaterialKey(m, "base_color", "0.1,0.2, 0.3");
  setMaterialKey(m, "mapping", "triplanar");
  setMaterialKey(m, "basis", "perlin");
  setMaterialKey(m, "description", "my own, with a comma");
  EXPECT_EQ(m.turb_power, 7.25f);
  EXPECT_EQ(m.seed, 123u);
  EXPECT_EQ(m.base_color, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(m.mapping, PatternMapping::Triplanar);
  EXPECT_EQ(m.basis, NoiseBasis::Perlin);
  EXPECT_EQ(m.description, "my own, with a comma");

  const Material before = m;
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "turb_power", "-2"); }),
            "--set: turb_power: expected a number in [0, 1000], got -2");
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "turb_power", "abc"); }).rfind("--set: turb_power: expected a number", 0), 0u);
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "base_color", "1,2"); }).rfind("--set: base_color: expected an array of 3", 0), 0u);
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "mapping", "cubic"); }).rfind("--set: mapping: expected one of", 0), 0u);
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "no_such_key", "1"); }).rfind("--set: no_such_key: unknown key", 0), 0u);
  EXPECT_EQ(errorOf([&] { setMaterialKey(m, "resolution", "16"); }).rfind("--set: turb_size:", 0), 0u);
  expectSame(m, before);  // a failed --set changes nothing
}

TEST(MaterialIoTest, EveryKeyCanBeSetFromTheCommandLine) {
  const Material cal = loadPreset("calacatta");
  const json j = materialToJson(cal);
  Material m;
  for (const auto& key : materialKeys()) {
    const json& v = j[key];
    std::string text;
    if (v.is_string()) text = v.get<std::string>();
    else if (v.is_array()) text = v[0].dump() + "," + v[1].dump() + "," + v[2].dump();
    else text = v.dump();
    setMaterialKey(m, key, text);
  }
  expectSame(m, cal);
}

}  // namespace
}  // namespace marble
