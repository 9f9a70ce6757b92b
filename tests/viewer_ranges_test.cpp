// The panel's slider ranges (the parameters' descriptions, src/marble/scene/material_params.cpp) against the preset format: both ends
// of every slider are values a preset file accepts (so whatever the panel makes can be saved and
// loaded), and every built-in preset sits inside its sliders. Section resets touch only their own
// section (src/app/viewer/material_sections.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "../src/app/viewer/material_sections.h"
#include "marble/scene/material_io.h"
#include "marble/scene/material_params.h"

namespace marble {
namespace {

// The parameters the panel shows with a slider.
std::vector<const ParamDesc*> sliders() {
  std::vector<const ParamDesc*> out;
  for (const auto& p : materialParams())
    if (p.slider.hi > p.slider.lo) out.push_back(&p);
  return out;
}

std::string num(float v) {
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}


namespace {
// A preset value as numbers: one for a scalar, three for an RGB triple.
std::vector<double> numbersOf(const nlohmann::json& v) {
  std::vector<double> values;
  if (v.is_array())
    for (const auto& c : v) values.push_back(c.get<double>());
  else
    values.push_back(v.get<double>());
  return values;
}
}  // namespace

TEST(ViewerRanges, BothEndsOfEverySliderAreAcceptedByPresetFiles) {
  EXPECT_GE(sliders().size(), 20u);
  for (const ParamDesc* p : sliders()) {
    const SliderSpec& r = p->slider;
    if (r.logarithmic) {
      EXPECT_GT(r.lo, 0.0f) << p->key;
    }
    for (float v : {r.lo, r.hi}) {
      Material m;
      const bool perChannel = p->type == ParamType::Vec3 || p->type == ParamType::Colour;
      const std::string value = perChannel ? num(v) + "," + num(v) + "," + num(v) : num(v);
      // turb_size may not exceed resolution; the panel clamps it the same way.
      if (std::string(p->key) == "turb_size") m.resolution = 4096;
      if (std::string(p->key) == "resolution") m.turb_size = 1;
      EXPECT_NO_THROW(setMaterialKey(m, p->key, value)) << p->key << " = " << value;
      EXPECT_NO_THROW(validateMaterial(m, "panel", "")) << p->key << " = " << value;
    }
  }
}

TEST(ViewerRanges, EveryNumericMaterialKeyHasASlider) {
  const nlohmann::json j = materialToJson(Material{});
  for (const auto& key : materialKeys()) {
    const auto& v = j[key];
    const bool numeric = v.is_number() || (v.is_array() && key.find("_color") == std::string::npos);
    if (numeric) {
      EXPECT_GT(findParam(key)->slider.hi, findParam(key)->slider.lo) << key << " has no slider range";
    }
  }
}

TEST(ViewerRanges, BuiltinPresetsSitInsideTheSliders) {
  for (const auto& info : builtinPresets()) {
    const nlohmann::json j = materialToJson(loadPreset(info.name));
    for (const ParamDesc* p : sliders()) {
      for (double d : numbersOf(j[p->key])) {
        EXPECT_GE(d, p->slider.lo) << info.name << ": " << p->key;
        EXPECT_LE(d, p->slider.hi) << info.name << ": " << p->key;
      }
    }
  }
}

// The digits after the '.' of a printf format ("%.4g" -> 4), as ImGui 1.86's
// ImParseFormatPrecision reads them; 3 (its default) without a '.'.
int formatPrecision(const char* format) {
  const char* dot = std::strchr(format, '.');
  return dot ? std::atoi(dot + 1) : 3;
}

TEST(ViewerRanges, ScatteringCoefficientSlidersAreLogarithmic) {
  // Issue: sigma_a of measured marble is 0.0021 /mm, a dark stone's 0.6; a linear slider over
  // [0, 2] gives the whole of marble's range a few pixels.
  EXPECT_TRUE(findParam("sigma_a_mm")->slider.logarithmic);
  EXPECT_TRUE(findParam("sigma_s_mm")->slider.logarithmic);
}

TEST(ViewerRanges, LogarithmicSlidersReachTheirLowerEnd) {
  // ImGui's logarithmic slider treats |v| < 10^-precision as zero: below that the slider's left
  // end would be stuck at the fudged epsilon, not at lo.
  for (const ParamDesc* p : sliders()) {
    const SliderSpec& r = p->slider;
    if (!r.logarithmic || p->type == ParamType::Int) continue;  // integer sliders print "%d"
    EXPECT_GE(r.lo, std::pow(10.0f, -static_cast<float>(formatPrecision(r.format))) * 0.999f) << p->key << " " << r.format;
  }
}

TEST(ViewerRanges, SlidersShowEveryPresetValueToOnePercent) {
  // What the slider prints must read back as the value: "%.2f" showed sigma_a 0.0021 as "0.00".
  for (const auto& info : builtinPresets()) {
    const nlohmann::json j = materialToJson(loadPreset(info.name));
    for (const ParamDesc* p : sliders()) {
      if (p->type != ParamType::Float && p->type != ParamType::Vec3) continue;  // whole numbers print "%d"
      for (double d : numbersOf(j[p->key])) {
        char shown[64];
        std::snprintf(shown, sizeof shown, p->slider.format, static_cast<float>(d));
        const double back = std::strtod(shown, nullptr);
        EXPECT_NEAR(back, d, 0.01 * std::abs(d)) << info.name << ": " << p->key << " = " << d << " shows as " << shown;
      }
    }
  }
}

TEST(ViewerSections, ResetTouchesOnlyItsSection) {
  const Material preset = loadPreset("nero-marquina");
  const Material edited = [] {
    Material m = loadPreset("carrara");
    m.turb_power = 13;
    return m;
  }();
  // Resetting every section gives back the preset's look (name and description are not sections).
  Material all = edited;
  for (const auto& g : paramGroups())
    if (g.id != ParamGroup::Identity) viewer::resetSection(all, preset, g.id);
  all.name = preset.name;
  all.description = preset.description;
  EXPECT_EQ(materialToJson(all), materialToJson(preset));
  // Each section: its own keys take the preset's values, every other key keeps the edited one.
  const nlohmann::json presetJson = materialToJson(preset), editedJson = materialToJson(edited);
  for (const auto& g : paramGroups()) {
    Material one = edited;
    viewer::resetSection(one, preset, g.id);
    const nlohmann::json j = materialToJson(one);
    for (const auto& p : materialParams())
      EXPECT_EQ(j[p.key], p.group == g.id ? presetJson[p.key] : editedJson[p.key]) << g.title << ": " << p.key;
  }
  // Negative control: the two presets differ in every group but the comparison models'.
  for (const auto& g : paramGroups())
    if (g.id != ParamGroup::Comparison) {
      EXPECT_FALSE(g.equal(edited, preset)) << g.title;
    }
}

TEST(ViewerSections, UnusedControlsNameTheModesThatUseThem) {
  const std::string tip = viewer::unusedTooltip(*findParam("k_schlick"), Material{}, RenderMode::Marble);
  EXPECT_NE(tip.find("'marble' mode does not read this; used by: paper."), std::string::npos) << tip;
  EXPECT_NE(viewer::unusedTooltip(*findParam("roughness"), Material{}, RenderMode::Paper).find("used by: marble."),
            std::string::npos);
}

}  // namespace
}  // namespace marble
