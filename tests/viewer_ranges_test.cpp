// The panel's slider ranges (src/app/viewer/param_ranges.h) against the preset format: both ends
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
#include "../src/app/viewer/param_ranges.h"
#include "marble/scene/material_io.h"

namespace marble {
namespace {

using viewer::kParamRanges;

std::string num(float v) {
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

bool isColourKey(const std::string& k) {  // per-channel keys, and the vein model's per-family triples
  return (k.rfind("sigma_", 0) == 0 && k != "oren_nayar_sigma") || k == "vein_spacing" || k == "vein_width" ||
         k == "vein_density" || k == "vein_normal";
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
  for (const auto& r : kParamRanges) {
    ASSERT_LT(r.lo, r.hi) << r.key;
    if (r.logarithmic) {
      EXPECT_GT(r.lo, 0.0f) << r.key;
    }
    for (float v : {r.lo, r.hi}) {
      Material m;
      const std::string value = isColourKey(r.key) ? num(v) + "," + num(v) + "," + num(v) : num(v);
      // turb_size may not exceed resolution; the panel clamps it the same way.
      if (std::string(r.key) == "turb_size") m.resolution = 4096;
      if (std::string(r.key) == "resolution") m.turb_size = 1;
      EXPECT_NO_THROW(setMaterialKey(m, r.key, value)) << r.key << " = " << value;
      EXPECT_NO_THROW(validateMaterial(m, "panel", "")) << r.key << " = " << value;
    }
  }
}

TEST(ViewerRanges, EveryNumericMaterialKeyHasASlider) {
  const nlohmann::json j = materialToJson(Material{});
  for (const auto& key : materialKeys()) {
    const auto& v = j[key];
    const bool numeric = v.is_number() || (v.is_array() && key.find("_color") == std::string::npos);
    if (numeric) {
      EXPECT_NE(viewer::rangeOf(key).key, nullptr) << key << " has no slider range";
    }
  }
}

TEST(ViewerRanges, BuiltinPresetsSitInsideTheSliders) {
  for (const auto& info : builtinPresets()) {
    const nlohmann::json j = materialToJson(loadPreset(info.name));
    for (const auto& r : kParamRanges) {
      for (double d : numbersOf(j[r.key])) {
        EXPECT_GE(d, r.lo) << info.name << ": " << r.key;
        EXPECT_LE(d, r.hi) << info.name << ": " << r.key;
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
  EXPECT_TRUE(viewer::rangeOf("sigma_a_mm").logarithmic);
  EXPECT_TRUE(viewer::rangeOf("sigma_s_mm").logarithmic);
}

TEST(ViewerRanges, LogarithmicSlidersReachTheirLowerEnd) {
  // ImGui's logarithmic slider treats |v| < 10^-precision as zero: below that the slider's left
  // end would be stuck at the fudged epsilon, not at lo.
  for (const auto& r : kParamRanges) {
    if (!r.logarithmic) continue;
    EXPECT_GE(r.lo, std::pow(10.0f, -static_cast<float>(formatPrecision(r.format))) * 0.999f) << r.key << " " << r.format;
  }
}

TEST(ViewerRanges, SlidersShowEveryPresetValueToOnePercent) {
  // What the slider prints must read back as the value: "%.2f" showed sigma_a 0.0021 as "0.00".
  for (const auto& info : builtinPresets()) {
    const nlohmann::json j = materialToJson(loadPreset(info.name));
    for (const auto& r : kParamRanges) {
      for (double d : numbersOf(j[r.key])) {
        char shown[64];
        std::snprintf(shown, sizeof shown, r.format, static_cast<float>(d));
        const double back = std::strtod(shown, nullptr);
        EXPECT_NEAR(back, d, 0.01 * std::abs(d)) << info.name << ": " << r.key << " = " << d << " shows as " << shown;
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
  for (auto s : {viewer::MaterialSection::Pattern, viewer::MaterialSection::Colour, viewer::MaterialSection::Subsurface,
                 viewer::MaterialSection::Reflectance})
    viewer::resetSection(all, preset, s);
  all.name = preset.name;
  all.description = preset.description;
  EXPECT_EQ(materialToJson(all), materialToJson(preset));
  // One section: its fields change, the others' do not.
  Material colourOnly = edited;
  viewer::resetSection(colourOnly, preset, viewer::MaterialSection::Colour);
  EXPECT_EQ(colourOnly.base_color, preset.base_color);
  EXPECT_EQ(colourOnly.turb_power, 13.0f);
  EXPECT_EQ(colourOnly.sigma_t, edited.sigma_t);
  EXPECT_EQ(colourOnly.k_schlick, edited.k_schlick);
}

}  // namespace
}  // namespace marble
