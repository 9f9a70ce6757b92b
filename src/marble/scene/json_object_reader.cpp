#include "marble/scene/json_object_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "marble/core/error.h"
#include "marble/core/json_limits.h"

namespace marble {

JsonObjectReader::JsonObjectReader(const json& obj, std::string file, std::string prefix, JsonWording wording)
    : obj_(obj), file_(std::move(file)), prefix_(std::move(prefix)), wording_(wording) {}

const nlohmann::json* JsonObjectReader::find(const std::string& key) {
  used_.push_back(key);
  auto it = obj_.find(key);
  return it == obj_.end() ? nullptr : &*it;
}

void JsonObjectReader::fail(const std::string& key, const std::string& problem) const {
  throw InputError(file_, prefix_ + key, problem);
}

std::string JsonObjectReader::describe(const json& v) { return std::string(v.type_name()) + " " + jsonExcerpt(v); }

std::string JsonObjectReader::bound(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool JsonObjectReader::number(const std::string& key, float& out, double lo, double hi) {
  const json* v = find(key);
  if (!v) return false;
  const std::string range = "expected a number in [" + bound(lo) + ", " + bound(hi) + "], got ";
  if (!v->is_number()) fail(key, (wording_ == JsonWording::Scene ? "expected a number, got " : range) + describe(*v));
  const double d = v->get<double>();
  if (!std::isfinite(d) || d < lo || d > hi) fail(key, range + jsonExcerpt(*v));
  out = static_cast<float>(d);
  return true;
}

bool JsonObjectReader::integer(const std::string& key, long long& out, long long lo, long long hi) {
  const json* v = find(key);
  if (!v) return false;
  const std::string range = "expected a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got ";
  if (wording_ == JsonWording::Scene && !v->is_number_integer()) fail(key, "expected a whole number, got " + describe(*v));
  if (!v->is_number()) fail(key, range + describe(*v));
  if (v->is_number_float()) {  // Material only: 2.0 is a whole number
    const double d = v->get<double>();
    if (!std::isfinite(d) || d != std::floor(d) || d < static_cast<double>(lo) || d > static_cast<double>(hi))
      fail(key, range + jsonExcerpt(*v));
    out = static_cast<long long>(d);
  } else if (v->is_number_unsigned()) {  // above LLONG_MAX it would wrap as a long long
    const auto u = v->get<unsigned long long>();
    if (u > static_cast<unsigned long long>(hi) || static_cast<long long>(u) < lo) fail(key, range + jsonExcerpt(*v));
    out = static_cast<long long>(u);
  } else {
    const long long i = v->get<long long>();
    if (i < lo || i > hi) fail(key, range + jsonExcerpt(*v));
    out = i;
  }
  return true;
}

bool JsonObjectReader::integer(const std::string& key, int& out, int lo, int hi) {
  long long i = 0;
  if (!integer(key, i, lo, hi)) return false;
  out = static_cast<int>(i);  // within [lo, hi]
  return true;
}

bool JsonObjectReader::vec3(const std::string& key, glm::vec3& out, double lo, double hi) {
  const json* v = find(key);
  if (!v) return false;
  const bool scene = wording_ == JsonWording::Scene;
  const std::string want =
      scene ? "expected an array of 3 numbers, got "
            : "expected an array of 3 numbers in [" + bound(lo) + ", " + bound(hi) + "], got ";
  if (!v->is_array() || v->size() != 3) fail(key, want + describe(*v));
  glm::vec3 r;
  for (int i = 0; i < 3; ++i) {
    const json& c = (*v)[static_cast<size_t>(i)];
    if (!c.is_number()) fail(key, want + describe(*v));
    const double d = c.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
      fail(key, scene ? "component " + std::to_string(i) + " must be in [" + bound(lo) + ", " + bound(hi) +
                            "], got " + jsonExcerpt(c)
                      : want + jsonExcerpt(*v));
    r[i] = static_cast<float>(d);
  }
  out = r;
  return true;
}

bool JsonObjectReader::boolean(const std::string& key, bool& out) {
  const json* v = find(key);
  if (!v) return false;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + describe(*v));
  out = v->get<bool>();
  return true;
}

bool JsonObjectReader::string(const std::string& key, std::string& out) {
  const json* v = find(key);
  if (!v) return false;
  if (!v->is_string()) fail(key, "expected a string, got " + describe(*v));
  out = v->get<std::string>();
  return true;
}

bool JsonObjectReader::choice(const std::string& key, std::span<const EnumChoice> table, int& out) {
  const json* v = find(key);
  if (!v) return false;
  std::string names;
  for (const auto& e : table) names += std::string(names.empty() ? "" : ", ") + "\"" + e.name + "\"";
  if (!v->is_string()) fail(key, "expected one of " + names + ", got " + describe(*v));
  const std::string s = v->get<std::string>();
  for (const auto& e : table)
    if (s == e.name) {
      out = e.value;
      return true;
    }
  fail(key, "expected one of " + names + ", got " + jsonExcerpt(*v));
}

const nlohmann::json* JsonObjectReader::object(const std::string& key) {
  const json* v = find(key);
  if (v && !v->is_object()) fail(key, "expected an object, got " + describe(*v));
  return v;
}

void JsonObjectReader::warnUnknown(std::vector<std::string>& warnings) const {
  for (auto it = obj_.begin(); it != obj_.end(); ++it)
    if (std::find(used_.begin(), used_.end(), it.key()) == used_.end())
      warnings.push_back(file_ + ": " + prefix_ + it.key() + ": unknown key" +
                         (wording_ == JsonWording::Material ? " '" + it.key() + "'" : "") + " (ignored)");
}

}  // namespace marble
