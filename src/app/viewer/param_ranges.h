#pragma once
// The panel's slider ranges, by material key. Kept apart from the ImGui code so a unit test
// (tests/viewer_ranges_test.cpp) can hold them against what preset files accept and what the
// built-in presets use: a slider whose end the loader rejects would let a user save a preset
// that cannot be loaded, and a slider narrower than a preset's value would surprise on touch.
// Ctrl+click on a slider still types any value the loader accepts.
#include <string_view>

namespace marble::viewer {

struct ParamRange {
  const char* key;
  float lo, hi;
  bool logarithmic;  // for parameters whose useful values span decades (sizes, exponents, coefficients)
  // printf format of the slider's number. ImGui also rounds dragged values to it, and its
  // logarithmic slider (1.86, SliderBehaviorT) treats values below 10^-p as 0, p being the
  // digits after the '.': a logarithmic range needs lo >= 10^-p (tests/viewer_ranges_test.cpp).
  const char* format = "%.3g";
};

inline constexpr ParamRange kParamRanges[] = {
    {"x_period", 0.0f, 20.0f, false},      {"y_period", 0.0f, 20.0f, false},
    {"z_period", 0.0f, 20.0f, false},      {"turb_power", 0.0f, 20.0f, false},
    {"turb_size", 1.0f, 1024.0f, true},    {"pattern_scale", 0.1f, 8.0f, true},
    {"vein_sharpness", 0.1f, 8.0f, true},  {"vein2_amount", 0.0f, 1.0f, false},
    {"sigma_t", 0.0f, 10.0f, false},       {"k_sss", 0.0f, 1.0f, false},
    {"k_schlick", 0.0f, 1.0f, false},      {"metalness", 0.0f, 1.0f, false},
    {"shininess", 1.0f, 512.0f, true},     {"oren_nayar_sigma", 0.0f, 1.5707f, false},
    // Measured coefficients span decades (marble's sigma_a is 0.002-0.007 /mm, a dark stone's 0.6):
    // logarithmic, with four significant digits so 0.0021 does not read 0.00.
    {"sigma_a_mm", 1.0e-4f, 2.0f, true, "%.4g"}, {"sigma_s_mm", 0.01f, 10.0f, true, "%.4g"},
    {"translucency", 0.0f, 2.0f, false},   {"ior", 1.0f, 3.0f, false},
    {"roughness", 0.0f, 1.0f, false},
    {"resolution", 16.0f, 1024.0f, true},  {"seed", 0.0f, 1.0e6f, false},
    // vein model (issue 16): spacings and widths span decades (a dominant vein 0.05, a hairline 0.002).
    {"vein_spacing", 0.01f, 4.0f, true},   {"vein_width", 1.0e-4f, 0.5f, true, "%.4g"},
    {"vein_density", 0.0f, 1.0f, false},   {"vein_normal", -1.0f, 1.0f, false},
    {"vein_stretch", 1.0f, 20.0f, true},   {"vein_warp", 0.0f, 2.0f, false},
    {"vein_pinch", 0.0f, 1.0f, false},     {"vein_softness", 0.0f, 1.0f, false},
    {"cloud_amount", 0.0f, 1.0f, false},   {"grain_amount", 0.0f, 1.0f, false},
    {"fragment_tint", 0.0f, 1.0f, false},
};

// The range of `key`; a zero range ({nullptr, 0, 0}) for a key without a slider.
constexpr ParamRange rangeOf(std::string_view key) {
  for (const auto& r : kParamRanges)
    if (key == r.key) return r;
  return {nullptr, 0.0f, 0.0f, false};
}

}  // namespace marble::viewer
