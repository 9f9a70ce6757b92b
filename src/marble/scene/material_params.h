#pragma once
// One description of every material parameter (issue 14). Each entry says what the parameter
// is (key, type, range, unit, default: the Material struct's), how the panel shows it (label,
// slider, tooltip), what docs/materials.md says of it, which render modes and passes read it,
// and the shader uniform that carries it. Everything that lists parameters iterates this
// table: JSON reading and writing (material_io.cpp), `--set`, range checks, the panel's
// widgets and section resets, the uniform upload (render/material_uniforms.h), the passes'
// cache invalidation (by group: groupsRead, sameGroups) and the docs' tables
// (materialDocTables). Adding a parameter: a field in its group's struct (material.h), an
// entry in material_params.cpp, the GLSL uniform that reads it, and its value in the presets.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "marble/scene/enum_choice.h"
#include "marble/scene/material.h"
#include "marble/scene/scene.h"

namespace marble {

// The groups, by what consumes them (material.h has one struct per group).
enum class ParamGroup { Identity, Pattern, BaseColour, Colour, VeinModel, PaperModel, Comparison, Scattering, Gloss };
inline constexpr int kParamGroupCount = 9;
using GroupSet = uint32_t;  // bit 1 << ParamGroup
constexpr GroupSet groupBit(ParamGroup g) { return 1u << static_cast<unsigned>(g); }

using ModeSet = uint32_t;  // bit 1 << RenderMode
constexpr ModeSet modeBit(RenderMode m) { return 1u << static_cast<unsigned>(m); }

// The passes that read material parameters (render/renderer.h orders them).
enum PassBit : uint32_t {
  kAlbedoPassBit = 1u << 0,    // the pattern per pixel: AlbedoPass, or `marble`'s PostPass evaluating it
  kLightingPassBit = 1u << 1,  // LightingPass
  kBlurPassBit = 1u << 2,      // SubsurfaceBlurPass
  kPostPassBit = 1u << 3,      // PostPass (`marble`: the reflection)
  kFloorPassBit = 1u << 4,     // FloorPass
  kBouncePassBit = 1u << 5,    // BouncePass (`marble`: the further bounces' albedo and F0)
};

enum class ParamType {
  Text,    // std::string (name, description)
  UInt,    // uint32_t
  Int,     // int
  Float,   // float
  Vec3,    // glm::vec3, a coefficient per channel
  Colour,  // glm::vec3, linear RGB
  Choice,  // an enum, by name
};

// A parameter's value, whatever its type: Text -> string; UInt, Int, Choice -> long long;
// Float -> float; Vec3, Colour -> vec3.
using ParamValue = std::variant<std::string, long long, float, glm::vec3>;

struct SliderSpec {
  float lo = 0, hi = 0;  // the panel's slider (Ctrl+click types any value the loader accepts)
  bool logarithmic = false;  // for values spanning decades
  // printf format of the slider's number. ImGui also rounds dragged values to it, and its
  // logarithmic slider (1.86, SliderBehaviorT) treats values below 10^-p as 0, p being the
  // digits after the '.': a logarithmic range needs lo >= 10^-p (tests/viewer_ranges_test.cpp).
  const char* format = "%.3g";
};

struct ParamDesc {
  const char* key;    // in files, scenes and `--set`
  ParamGroup group;
  ParamType type;
  double lo, hi;      // what files and `--set` accept (each channel, for Vec3 and Colour)
  const char* atMost; // another key whose value bounds this one from above, or nullptr
  const char* unit;   // "" for none
  const char* label;  // the panel's
  const char* tooltip;
  const char* doc;    // docs/materials.md's "meaning" column (Markdown)
  ModeSet modes;      // the render modes whose picture it changes
  uint32_t passes;    // PassBit: the passes that read it
  const char* uniform;  // GLSL uniform carrying it (the enum's integer for a Choice), or nullptr
  std::span<const EnumChoice> choices;  // Choice only
  SliderSpec slider;  // Float, Vec3, Int; hi of 0: no slider
  ParamValue (*get)(const Material&);
  void (*set)(Material&, const ParamValue&);
  // Whether the value is used, given the material's other values (the vein model's keys only
  // with vein_model network or breccia, sigma_a_mm only in the coefficient form, ...); nullptr:
  // always. `inactive` says when it is not ("the vein model is \"paper\"") for the panel's
  // tooltip and `--set`'s warning; hideInactive: the panel hides it then (a whole model's keys)
  // instead of greying it.
  bool (*active)(const Material&) = nullptr;
  const char* inactive = nullptr;
  bool hideInactive = false;
  // The value the shader gets where it is not the stored one (vein_normal: normalized); nullptr: get.
  ParamValue (*uniformValue)(const Material&) = nullptr;
};

// Whether `p` is used with `m`'s other values (ParamDesc::active).
inline bool paramActive(const ParamDesc& p, const Material& m) { return !p.active || p.active(m); }

struct ParamGroupDesc {
  ParamGroup id;
  const char* title;  // the panel's section and the docs' heading
  const char* what;   // one line: what reads it
  bool (*equal)(const Material&, const Material&);
  void (*assign)(Material& to, const Material& from);  // this group's fields only
};

std::span<const ParamDesc> materialParams();  // in file order
const ParamDesc* findParam(std::string_view key);  // nullptr when unknown
std::span<const ParamGroupDesc> paramGroups();
const ParamGroupDesc& groupOf(ParamGroup g);

// The groups holding a parameter that one of `passes` reads in `mode`.
GroupSet groupsRead(uint32_t passes, RenderMode mode);
// Whether a and b agree on every group in `groups`.
bool sameGroups(const Material& a, const Material& b, GroupSet groups);

bool modeReads(const ParamDesc& p, RenderMode mode);
// "paper, subsurface": the modes in `modes`, by their command-line names.
std::string modeNames(ModeSet modes);

// The value as files write it ("solid", 5, [1, 2, 3]) for messages and docs.
std::string formatValue(const ParamDesc& p, const ParamValue& v);
const char* choiceName(const ParamDesc& p, long long value);  // the first choice's for an unknown value

// docs/materials.md's parameter tables, one per group, between <!-- params:GROUP --> and
// <!-- /params --> markers: `text` with each marked region replaced by the table made now.
std::string withMaterialDocTables(const std::string& text);

// How a field maps to a ParamValue (material_params.cpp builds each entry with these).
template <auto Member>
ParamValue getField(const Material& m) {
  const auto& v = m.*Member;
  using T = std::remove_cvref_t<decltype(v)>;
  if constexpr (std::is_same_v<T, std::string>) return v;
  else if constexpr (std::is_enum_v<T> || std::is_integral_v<T>) return static_cast<long long>(v);
  else return v;  // float, glm::vec3
}
template <auto Member>
void setField(Material& m, const ParamValue& v) {
  auto& field = m.*Member;
  using T = std::remove_cvref_t<decltype(field)>;
  if constexpr (std::is_same_v<T, std::string>) field = std::get<std::string>(v);
  else if constexpr (std::is_enum_v<T> || std::is_integral_v<T>) field = static_cast<T>(std::get<long long>(v));
  else field = std::get<T>(v);
}

}  // namespace marble
