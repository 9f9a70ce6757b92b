#include "marble/scene/material_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/input_file.h"
#include "marble/core/json_limits.h"
#include "marble/scene/embedded_presets.h"
#include "marble/scene/json_object_reader.h"
#include "marble/scene/material_params.h"
#include "marble/scene/material_scattering.h"

namespace marble {
namespace {

using json = nlohmann::json;

constexpr int kMaxPresetDepth = 8;
constexpr std::uintmax_t kMaxJsonBytes = 64u << 20;

std::string describe(const json& v) { return JsonObjectReader::describe(v); }
std::string fmt(double v) { return JsonObjectReader::bound(v); }

// The shortest decimal that reads back as exactly `f` (through double, as nlohmann stores it).
json floatJson(float f) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
  if (ec == std::errc()) {
    const double d = std::strtod(std::string(buf, end).c_str(), nullptr);
    if (static_cast<float>(d) == f) return d;
  }
  return static_cast<double>(f);
}

const std::vector<std::string>& keyList() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& p : materialParams()) k.emplace_back(p.key);
    return k;
  }();
  return keys;
}

// The value of parameter `p`, read from the reader's object (where it is present), checked
// against its type and range.
ParamValue readValue(const ParamDesc& p, JsonObjectReader& r) {
  switch (p.type) {
    case ParamType::Text: {
      std::string text;
      r.string(p.key, text);
      return text;
    }
    case ParamType::UInt:
    case ParamType::Int: {
      long long i = 0;
      r.integer(p.key, i, static_cast<long long>(p.lo), static_cast<long long>(p.hi));
      return i;
    }
    case ParamType::Float: {
      float f = 0.0f;
      r.number(p.key, f, p.lo, p.hi);
      return f;
    }
    case ParamType::Vec3:
    case ParamType::Colour: {
      glm::vec3 c(0.0f);
      r.vec3(p.key, c, p.lo, p.hi);
      return c;
    }
    case ParamType::Choice: {
      int c = 0;
      r.choice(p.key, p.choices, c);
      return static_cast<long long>(c);
    }
  }
  return {};
}

json toJson(const ParamDesc& p, const ParamValue& v) {
  switch (p.type) {
    case ParamType::Text: return std::get<std::string>(v);
    case ParamType::UInt:
    case ParamType::Int: return std::get<long long>(v);
    case ParamType::Float: return floatJson(std::get<float>(v));
    case ParamType::Vec3:
    case ParamType::Colour: {
      const glm::vec3 c = std::get<glm::vec3>(v);
      return json::array({floatJson(c.x), floatJson(c.y), floatJson(c.z)});
    }
    case ParamType::Choice: return choiceName(p, std::get<long long>(v));
  }
  return nullptr;
}

// Sets `key` of the reader's object (present there) in `m`; an unknown key is left alone, for
// the reader's warnUnknown.
void applyKey(Material& m, const std::string& key, JsonObjectReader& r) {
  if (const ParamDesc* p = findParam(key)) p->set(m, readValue(*p, r));
}

// Every key of the reader's object `j` in the file's order (so the first bad key in it is the
// one reported), then a warning for each unknown one.
void applyKeys(Material& m, const json& j, JsonObjectReader& r, std::vector<std::string>& warnings) {
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "preset") applyKey(m, it.key(), r);
  r.warnUnknown(warnings);
}

// Which scattering form an object of keys selects (material.h, "the same stone in Blender's
// terms"): an explicit "scattering" decides; otherwise subsurface_radius_mm selects the radius
// form and sigma_a_mm or sigma_s_mm the coefficient form, starting from the coefficients the
// material had in effect (so a key left out keeps the stone's value). Both at once is an error:
// which one was meant cannot be known.
void selectScatteringForm(Material& m, bool hasForm, bool hasRadius, bool hasSigma, const std::string& file,
                          const std::string& placePrefix) {
  if (hasForm) return;
  if (hasRadius && hasSigma)
    throw InputError(file, placePrefix + "subsurface_radius_mm",
                     "give either subsurface_radius_mm (Blender's Principled BSDF, with base_color and ior) or "
                     "sigma_a_mm/sigma_s_mm, not both (or say which with \"scattering\")");
  if (hasRadius) {
    m.scattering = ScatteringForm::Radius;
  } else if (hasSigma) {
    resolveScattering(m);
    m.scattering = ScatteringForm::Coefficients;
  }
}

void selectScatteringForm(Material& m, const json& j, const std::string& file, const std::string& placePrefix) {
  selectScatteringForm(m, j.contains("scattering"), j.contains("subsurface_radius_mm"),
                       j.contains("sigma_a_mm") || j.contains("sigma_s_mm"), file, placePrefix);
}

std::string builtinFileName(const std::string& name) { return name + ".json"; }

std::string knownPresetNames() {
  std::string s;
  for (const auto& p : builtinPresets()) s += (s.empty() ? "" : ", ") + p.name;
  return s;
}

json parseJson(const std::string& text, const std::string& file) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(file, "", "empty file");
  checkJsonNesting(text, file);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for numbers like 1e400
    throw InputError(file, "", "invalid JSON: " + jsonErrorText(e.what()));
  }
}

Material loadPresetImpl(const std::string& nameOrPath, const std::filesystem::path& relativeTo, int depth,
                        std::vector<std::string>& warnings) {
  if (depth > kMaxPresetDepth) throw InputError(nameOrPath, "preset", "presets nest too deeply (a cycle?)");
  std::string text, file;
  const auto& table = embeddedPresets();
  if (auto it = table.find(builtinFileName(nameOrPath)); it != table.end()) {
    text = it->second;
    file = "builtin:" + nameOrPath;
  } else {
    std::filesystem::path path(nameOrPath);
    if (path.is_relative() && !relativeTo.empty()) path = relativeTo / path;
    file = path.string();
    std::error_code ec;
    // symlink_status: a symbolic link loop or a dangling link is there, and InputFile says what it is.
    if (nameOrPath.empty() || !std::filesystem::exists(std::filesystem::symlink_status(path, ec))) {
      const bool looksLikePath = nameOrPath.find('/') != std::string::npos || path.extension() == ".json";
      throw InputError(nameOrPath.empty() ? std::string("\"\"") : nameOrPath, "",
                       looksLikePath ? "no such file" : "not a built-in preset (" + knownPresetNames() + ") nor a file");
    }
    // A regular file only (a FIFO or /dev/zero would never end), and not absurdly large.
    InputFile in(path, file, "a file");
    if (in.size() > kMaxJsonBytes) throw InputError(file, "", "is larger than 64 MiB; not a preset");
    text = in.readAll(kMaxJsonBytes);
  }
  const json j = parseJson(text, file);
  if (!j.is_object()) throw InputError(file, "", "expected a JSON object at the top level, got " + describe(j));
  Material m;
  std::filesystem::path dir = std::filesystem::path(file).parent_path();
  if (file.rfind("builtin:", 0) == 0) dir.clear();
  JsonObjectReader r(j, file, "", JsonWording::Material);
  // "preset" inside a preset file: a base to start from.
  if (const json* base = r.find("preset")) {
    if (!base->is_string()) r.fail("preset", "expected a preset name or path, got " + describe(*base));
    m = loadPresetImpl(base->get<std::string>(), dir, depth + 1, warnings);
  }
  selectScatteringForm(m, j, file, "");
  applyKeys(m, j, r, warnings);
  validateMaterial(m, file, "");
  resolveScattering(m);
  return m;
}

}  // namespace

std::vector<std::string> materialKeys() { return keyList(); }

std::vector<PresetInfo> builtinPresets() {
  std::vector<PresetInfo> out;
  for (const auto& [fileName, text] : embeddedPresets()) {
    const auto dot = fileName.rfind(".json");
    if (dot == std::string::npos) continue;
    PresetInfo info{fileName.substr(0, dot), ""};
    try {
      const json j = json::parse(text);
      if (j.is_object() && j.contains("description") && j["description"].is_string())
        info.description = j["description"].get<std::string>();
    } catch (const json::exception&) {
      info.description = "(invalid JSON)";
    }
    out.push_back(std::move(info));
  }
  std::sort(out.begin(), out.end(), [](const PresetInfo& a, const PresetInfo& b) { return a.name < b.name; });
  return out;
}

Material loadPreset(const std::string& nameOrPath, std::vector<std::string>* warnings) {
  std::vector<std::string> local;
  Material m = loadPresetImpl(nameOrPath, {}, 0, warnings ? *warnings : local);
  if (!warnings)
    for (const auto& w : local) std::cerr << "warning: " << printable(w, kMessageLineLimit) << "\n";
  return m;
}

void validateMaterial(const Material& m, const std::string& file, const std::string& placePrefix) {
  for (const auto& p : materialParams()) {
    if (!p.atMost) continue;
    const ParamDesc& bound = *findParam(p.atMost);
    const auto toDouble = [](const ParamValue& v) {
      return std::holds_alternative<float>(v) ? static_cast<double>(std::get<float>(v))
                                              : static_cast<double>(std::get<long long>(v));
    };
    const double value = toDouble(p.get(m)), hi = toDouble(bound.get(m));
    if (value > hi)
      throw InputError(file, placePrefix + p.key,
                       "expected a number in [" + fmt(p.lo) + ", " + p.atMost + " = " + fmt(hi) + "], got " + fmt(value));
  }
  if (m.vein_normal == glm::vec3(0.0f))
    throw InputError(file, placePrefix + "vein_normal", "expected a nonzero direction, got [0, 0, 0]");
}

void applyMaterialJson(Material& m, const json& j, const std::string& file, const std::string& placePrefix,
                       std::vector<std::string>& warnings) {
  if (!j.is_object()) throw InputError(file, placePrefix.empty() ? "" : placePrefix.substr(0, placePrefix.size() - 1),
                                       "expected an object, got " + describe(j));
  JsonObjectReader r(j, file, placePrefix, JsonWording::Material);
  if (const json* base = r.find("preset")) {
    if (!base->is_string()) r.fail("preset", "expected a preset name or path, got " + describe(*base));
    std::filesystem::path dir;
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) dir = std::filesystem::path(file).parent_path();
    try {
      m = loadPresetImpl(base->get<std::string>(), dir, 1, warnings);
    } catch (const InputError& e) {
      r.fail("preset", e.what());
    }
  }
  selectScatteringForm(m, j, file, placePrefix);
  applyKeys(m, j, r, warnings);
  validateMaterial(m, file, placePrefix);
  resolveScattering(m);
}

void setMaterialKey(Material& m, const std::string& key, const std::string& value) {
  const auto& keys = keyList();
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
    std::string all;
    for (const auto& k : keys) all += (all.empty() ? "" : ", ") + k;
    throw InputError("--set", key, "unknown key (known: " + all + ")");
  }
  auto parseNumber = [&key](const std::string& s, json& out) {
    const char* b = s.data();
    const char* e = s.data() + s.size();
    while (b < e && *b == ' ') ++b;
    while (e > b && e[-1] == ' ') --e;
    if (b == e) return false;
    long long i = 0;
    if (auto r = std::from_chars(b, e, i); r.ec == std::errc() && r.ptr == e) {
      out = i;
      return true;
    }
    double d = 0;
    if (auto r = std::from_chars(b, e, d); r.ec == std::errc() && r.ptr == e) {
      // nan and inf parse, but JSON cannot hold them: they would arrive as null.
      if (!std::isfinite(d)) throw InputError("--set", key, "expected a finite number, got " + std::string(b, e));
      out = d;
      return true;
    }
    return false;
  };
  json v;
  if (findParam(key)->type == ParamType::Text) {
    v = value;
  } else if (value.find(',') != std::string::npos) {
    v = json::array();
    size_t start = 0;
    while (true) {
      const size_t comma = value.find(',', start);
      const std::string part = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      json n;
      if (!parseNumber(part, n)) {
        v = value;  // not a list of numbers: let the key's check report it
        break;
      }
      v.push_back(n);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  } else if (!parseNumber(value, v)) {
    v = value;
  }
  Material copy = m;
  selectScatteringForm(copy, false, key == "subsurface_radius_mm", key == "sigma_a_mm" || key == "sigma_s_mm", "--set", "");
  json one = json::object();
  one[key] = v;
  JsonObjectReader r(one, "--set", "", JsonWording::Material);
  applyKey(copy, key, r);  // a known key (checked above)
  validateMaterial(copy, "--set", "");
  resolveScattering(copy);
  m = copy;
}

json materialToJson(const Material& m) {
  json j = json::object();
  for (const auto& p : materialParams()) j[p.key] = toJson(p, p.get(m));
  return j;
}

void saveMaterial(const std::filesystem::path& path, const Material& m) {
  // Keys in materialKeys() order, for a readable file.
  const json j = materialToJson(m);
  std::string out = "{\n";
  const auto& keys = keyList();
  for (size_t i = 0; i < keys.size(); ++i)
    out += "  \"" + keys[i] + "\": " + j[keys[i]].dump() + (i + 1 < keys.size() ? ",\n" : "\n");
  out += "}\n";
  writeFileAtomically(path, out);
}

}  // namespace marble
