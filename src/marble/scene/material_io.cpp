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

namespace marble {
namespace {

using json = nlohmann::json;

constexpr int kMaxPresetDepth = 8;
constexpr std::uintmax_t kMaxJsonBytes = 64u << 20;

std::string describe(const json& v) { return std::string(v.type_name()) + " " + jsonExcerpt(v); }

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

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

struct EnumName {
  int value;
  const char* name;
};
const EnumName kBasis[] = {{static_cast<int>(NoiseBasis::Value), "value"}, {static_cast<int>(NoiseBasis::Perlin), "perlin"}};
const EnumName kMapping[] = {{static_cast<int>(PatternMapping::Planar), "planar"},
                             {static_cast<int>(PatternMapping::Triplanar), "triplanar"},
                             {static_cast<int>(PatternMapping::Solid), "solid"}};
const EnumName kOrder[] = {{static_cast<int>(ShadingOrder::SubsurfaceFirst), "sss-first"},
                           {static_cast<int>(ShadingOrder::ReflectanceFirst), "schlick-first"}};
const EnumName kVeinModel[] = {{static_cast<int>(VeinModel::Paper), "paper"},
                               {static_cast<int>(VeinModel::Network), "network"},
                               {static_cast<int>(VeinModel::Breccia), "breccia"}};
const EnumName kCos[] = {{static_cast<int>(SchlickCosine::HdotV), "hv"}, {static_cast<int>(SchlickCosine::HdotN), "hn"}};

template <size_t N>
const char* enumName(const EnumName (&table)[N], int value) {
  for (const auto& e : table)
    if (e.value == value) return e.name;
  return table[0].name;
}

// Applies one key; returns false for an unknown key. Throws InputError(file, place, ...).
class KeySetter {
public:
  KeySetter(const json& v, const std::string& file, const std::string& place) : v_(v), file_(file), place_(place) {}

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(file_, place_, problem); }

  float number(double lo, double hi) const {
    if (!v_.is_number()) fail("expected a number in [" + fmt(lo) + ", " + fmt(hi) + "], got " + describe(v_));
    const double d = v_.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
      fail("expected a number in [" + fmt(lo) + ", " + fmt(hi) + "], got " + jsonExcerpt(v_));
    return static_cast<float>(d);
  }

  long long integer(long long lo, long long hi) const {
    const std::string want = "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
    if (!v_.is_number()) fail(want + describe(v_));
    if (v_.is_number_float()) {
      const double d = v_.get<double>();
      if (!std::isfinite(d) || d != std::floor(d) || d < static_cast<double>(lo) || d > static_cast<double>(hi))
        fail(want + jsonExcerpt(v_));
      return static_cast<long long>(d);
    }
    if (v_.is_number_unsigned()) {
      const auto u = v_.get<unsigned long long>();
      if (u > static_cast<unsigned long long>(hi) || static_cast<long long>(u) < lo) fail(want + jsonExcerpt(v_));
      return static_cast<long long>(u);
    }
    const long long i = v_.get<long long>();
    if (i < lo || i > hi) fail(want + jsonExcerpt(v_));
    return i;
  }

  glm::vec3 color(double lo, double hi) const {
    const std::string want = "expected an array of 3 numbers in [" + fmt(lo) + ", " + fmt(hi) + "], got ";
    if (!v_.is_array() || v_.size() != 3) fail(want + describe(v_));
    glm::vec3 r;
    for (int i = 0; i < 3; ++i) {
      const json& c = v_[static_cast<size_t>(i)];
      if (!c.is_number()) fail(want + describe(v_));
      const double d = c.get<double>();
      if (!std::isfinite(d) || d < lo || d > hi) fail(want + jsonExcerpt(v_));
      r[i] = static_cast<float>(d);
    }
    return r;
  }

  std::string string() const {
    if (!v_.is_string()) fail("expected a string, got " + describe(v_));
    return v_.get<std::string>();
  }

  template <size_t N>
  int choice(const EnumName (&table)[N]) const {
    std::string names;
    for (const auto& e : table) names += std::string(names.empty() ? "" : ", ") + "\"" + e.name + "\"";
    if (!v_.is_string()) fail("expected one of " + names + ", got " + describe(v_));
    const std::string s = v_.get<std::string>();
    for (const auto& e : table)
      if (s == e.name) return e.value;
    fail("expected one of " + names + ", got " + jsonExcerpt(v_));
  }

private:
  const json& v_;
  const std::string& file_;
  const std::string& place_;
};

const std::vector<std::string>& keyList() {
  static const std::vector<std::string> keys = {
      "name",           "description",  "seed",          "resolution", "basis",       "mapping",
      "x_period",       "y_period",     "z_period",      "turb_power", "turb_size",   "pattern_scale",
      "base_color",     "vein_color",   "vein2_color",   "vein_sharpness", "vein2_amount", "sigma_t",
      "k_sss",          "k_schlick",    "metalness",     "order",      "schlick_cos", "shininess",
      "oren_nayar_sigma", "sigma_a_mm", "sigma_s_mm", "ior", "roughness", "translucency",
      // vein model (issue 16)
      "vein_model", "vein_spacing", "vein_width", "vein_density", "vein_normal", "vein_stretch", "vein_warp",
      "vein_pinch", "vein_softness", "vein3_color", "cloud_color", "cloud_amount", "grain_amount", "fragment_tint"};
  return keys;
}

bool applyKey(Material& m, const std::string& key, const json& v, const std::string& file, const std::string& place) {
  const KeySetter s(v, file, place);
  if (key == "name") m.name = s.string();
  else if (key == "description") m.description = s.string();
  else if (key == "seed") m.seed = static_cast<uint32_t>(s.integer(0, 4294967295LL));
  else if (key == "resolution") m.resolution = static_cast<int>(s.integer(8, 4096));
  else if (key == "basis") m.basis = static_cast<NoiseBasis>(s.choice(kBasis));
  else if (key == "mapping") m.mapping = static_cast<PatternMapping>(s.choice(kMapping));
  else if (key == "x_period") m.x_period = s.number(-1000, 1000);
  else if (key == "y_period") m.y_period = s.number(-1000, 1000);
  else if (key == "z_period") m.z_period = s.number(-1000, 1000);
  else if (key == "turb_power") m.turb_power = s.number(0, 1000);
  else if (key == "turb_size") m.turb_size = s.number(1, 4096);
  else if (key == "pattern_scale") m.pattern_scale = s.number(0.001, 1000);
  else if (key == "base_color") m.base_color = s.color(0, 1);
  else if (key == "vein_color") m.vein_color = s.color(0, 1);
  else if (key == "vein2_color") m.vein2_color = s.color(0, 1);
  else if (key == "vein_sharpness") m.vein_sharpness = s.number(0.05, 20);
  else if (key == "vein2_amount") m.vein2_amount = s.number(0, 1);
  else if (key == "sigma_t") m.sigma_t = s.color(0, 1000);
  else if (key == "k_sss") m.k_sss = s.number(0, 1);
  else if (key == "k_schlick") m.k_schlick = s.number(0, 1);
  else if (key == "metalness") m.metalness = s.number(0, 1);
  else if (key == "order") m.order = static_cast<ShadingOrder>(s.choice(kOrder));
  else if (key == "schlick_cos") m.schlick_cos = static_cast<SchlickCosine>(s.choice(kCos));
  else if (key == "shininess") m.shininess = s.number(0, 10000);
  else if (key == "oren_nayar_sigma") m.oren_nayar_sigma = s.number(0, 1.5708);
  else if (key == "sigma_a_mm") m.sigma_a_mm = s.color(0, 1000);
  else if (key == "sigma_s_mm") m.sigma_s_mm = s.color(0, 10000);
  else if (key == "ior") m.ior = s.number(1.0, 3.0);
  else if (key == "roughness") m.roughness = s.number(0.0, 1.0);
  else if (key == "translucency") m.translucency = s.number(0.0, 10.0);
  // vein model (issue 16)
  else if (key == "vein_model") m.vein_model = static_cast<VeinModel>(s.choice(kVeinModel));
  else if (key == "vein_spacing") m.vein_spacing = s.color(0.005, 100);
  else if (key == "vein_width") m.vein_width = s.color(0, 10);
  else if (key == "vein_density") m.vein_density = s.color(0, 1);
  else if (key == "vein_normal") m.vein_normal = s.color(-1, 1);
  else if (key == "vein_stretch") m.vein_stretch = s.number(1, 20);
  else if (key == "vein_warp") m.vein_warp = s.number(0, 10);
  else if (key == "vein_pinch") m.vein_pinch = s.number(0, 1);
  else if (key == "vein_softness") m.vein_softness = s.number(0, 1);
  else if (key == "vein3_color") m.vein3_color = s.color(0, 1);
  else if (key == "cloud_color") m.cloud_color = s.color(0, 1);
  else if (key == "cloud_amount") m.cloud_amount = s.number(0, 1);
  else if (key == "grain_amount") m.grain_amount = s.number(0, 1);
  else if (key == "fragment_tint") m.fragment_tint = s.number(0, 1);
  else return false;
  return true;
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
  // "preset" inside a preset file: a base to start from.
  if (auto it = j.find("preset"); it != j.end()) {
    if (!it->is_string()) throw InputError(file, "preset", "expected a preset name or path, got " + describe(*it));
    m = loadPresetImpl(it->get<std::string>(), dir, depth + 1, warnings);
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "preset") continue;
    if (!applyKey(m, it.key(), it.value(), file, it.key()))
      warnings.push_back(file + ": " + it.key() + ": unknown key '" + it.key() + "' (ignored)");
  }
  validateMaterial(m, file, "");
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
  if (m.turb_size > static_cast<float>(m.resolution))
    throw InputError(file, placePrefix + "turb_size",
                     "expected a number in [1, resolution = " + std::to_string(m.resolution) + "], got " + fmt(m.turb_size));
  if (m.vein_normal == glm::vec3(0.0f))
    throw InputError(file, placePrefix + "vein_normal", "expected a nonzero direction, got [0, 0, 0]");
}

void applyMaterialJson(Material& m, const json& j, const std::string& file, const std::string& placePrefix,
                       std::vector<std::string>& warnings) {
  if (!j.is_object()) throw InputError(file, placePrefix.empty() ? "" : placePrefix.substr(0, placePrefix.size() - 1),
                                       "expected an object, got " + describe(j));
  if (auto it = j.find("preset"); it != j.end()) {
    if (!it->is_string())
      throw InputError(file, placePrefix + "preset", "expected a preset name or path, got " + describe(*it));
    std::filesystem::path dir;
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) dir = std::filesystem::path(file).parent_path();
    try {
      m = loadPresetImpl(it->get<std::string>(), dir, 1, warnings);
    } catch (const InputError& e) {
      throw InputError(file, placePrefix + "preset", e.what());
    }
  }
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "preset") continue;
    if (!applyKey(m, it.key(), it.value(), file, placePrefix + it.key()))
      warnings.push_back(file + ": " + placePrefix + it.key() + ": unknown key '" + it.key() + "' (ignored)");
  }
  validateMaterial(m, file, placePrefix);
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
  if (key == "name" || key == "description") {
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
  applyKey(copy, key, v, "--set", key);
  validateMaterial(copy, "--set", "");
  m = copy;
}

json materialToJson(const Material& m) {
  json j = json::object();
  j["name"] = m.name;
  j["description"] = m.description;
  j["seed"] = m.seed;
  j["resolution"] = m.resolution;
  j["basis"] = enumName(kBasis, static_cast<int>(m.basis));
  j["mapping"] = enumName(kMapping, static_cast<int>(m.mapping));
  j["x_period"] = floatJson(m.x_period);
  j["y_period"] = floatJson(m.y_period);
  j["z_period"] = floatJson(m.z_period);
  j["turb_power"] = floatJson(m.turb_power);
  j["turb_size"] = floatJson(m.turb_size);
  j["pattern_scale"] = floatJson(m.pattern_scale);
  auto col = [](glm::vec3 c) { return json::array({floatJson(c.x), floatJson(c.y), floatJson(c.z)}); };
  j["base_color"] = col(m.base_color);
  j["vein_color"] = col(m.vein_color);
  j["vein2_color"] = col(m.vein2_color);
  j["vein_sharpness"] = floatJson(m.vein_sharpness);
  j["vein2_amount"] = floatJson(m.vein2_amount);
  j["sigma_t"] = col(m.sigma_t);
  j["k_sss"] = floatJson(m.k_sss);
  j["k_schlick"] = floatJson(m.k_schlick);
  j["metalness"] = floatJson(m.metalness);
  j["order"] = enumName(kOrder, static_cast<int>(m.order));
  j["schlick_cos"] = enumName(kCos, static_cast<int>(m.schlick_cos));
  j["shininess"] = floatJson(m.shininess);
  j["oren_nayar_sigma"] = floatJson(m.oren_nayar_sigma);
  j["sigma_a_mm"] = col(m.sigma_a_mm);
  j["sigma_s_mm"] = col(m.sigma_s_mm);
  j["ior"] = floatJson(m.ior);
  j["roughness"] = floatJson(m.roughness);
  j["translucency"] = floatJson(m.translucency);
  // vein model (issue 16)
  j["vein_model"] = enumName(kVeinModel, static_cast<int>(m.vein_model));
  j["vein_spacing"] = col(m.vein_spacing);
  j["vein_width"] = col(m.vein_width);
  j["vein_density"] = col(m.vein_density);
  j["vein_normal"] = col(m.vein_normal);
  j["vein_stretch"] = floatJson(m.vein_stretch);
  j["vein_warp"] = floatJson(m.vein_warp);
  j["vein_pinch"] = floatJson(m.vein_pinch);
  j["vein_softness"] = floatJson(m.vein_softness);
  j["vein3_color"] = col(m.vein3_color);
  j["cloud_color"] = col(m.cloud_color);
  j["cloud_amount"] = floatJson(m.cloud_amount);
  j["grain_amount"] = floatJson(m.grain_amount);
  j["fragment_tint"] = floatJson(m.fragment_tint);
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
