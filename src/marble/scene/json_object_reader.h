#pragma once
// The one reader of JSON objects for scenes and materials: it reads a field, checks its type and
// range, throws InputError(file, prefix + key, problem) naming file and field, and remembers
// which keys were read so the rest can be warned about as unknown.
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "marble/scene/enum_choice.h"

namespace marble {

// How the reader words its messages. Scene fields and material keys grew different wordings
// (the material's always states the range, and takes 2.0 for a whole number, since `--set`
// hands it numbers parsed from text); tests/bad_inputs_cli.cpp, docs/bad-inputs.md and users'
// scripts rely on both, so the difference is kept, here and nowhere else:
//                      Scene                                   Material
//   number, type       expected a number, got T                expected a number in [lo, hi], got T
//   whole number, 2.0  expected a whole number, got T          accepted
//   whole number, type expected a whole number, got T          expected a whole number in [lo, hi], got T
//   3 numbers, shape   expected an array of 3 numbers, got T   expected an array of 3 numbers in [lo, hi], got T
//   3 numbers, range   component i must be in [lo, hi], got C  expected an array of 3 numbers in [lo, hi], got A
//   unknown key        F: P: unknown key (ignored)             F: P: unknown key 'K' (ignored)
// (T: the value's type and excerpt; C: the component; A: the array; F: file; P: prefix + key.)
enum class JsonWording { Scene, Material };

class JsonObjectReader {
public:
  using json = nlohmann::json;
  // `prefix` goes before each key in messages ("camera.", "material.", or "").
  JsonObjectReader(const json& obj, std::string file, std::string prefix, JsonWording wording);

  // The field `key` (nullptr when absent), counted as read.
  const json* find(const std::string& key);
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  // Each reads `key` into `out` if present (returns whether it was), checked against its
  // type and [lo, hi]; out is left alone when absent.
  bool number(const std::string& key, float& out, double lo, double hi);
  bool integer(const std::string& key, long long& out, long long lo, long long hi);
  bool integer(const std::string& key, int& out, int lo, int hi);
  bool vec3(const std::string& key, glm::vec3& out, double lo, double hi);
  bool boolean(const std::string& key, bool& out);
  bool string(const std::string& key, std::string& out);
  // One of `table`'s names: "expected one of "a", "b", got ...".
  bool choice(const std::string& key, std::span<const EnumChoice> table, int& out);
  // An object (nullptr when absent).
  const json* object(const std::string& key);

  // Appends a warning for each key of the object that no call above asked for.
  void warnUnknown(std::vector<std::string>& warnings) const;

  // A value's type and excerpt, for "got ..." ("string \"abc\"").
  static std::string describe(const json& v);
  // A bound as messages print it (ostream's default: 6 significant digits).
  static std::string bound(double v);

private:
  const json& obj_;
  std::string file_, prefix_;
  JsonWording wording_;
  std::vector<std::string> used_;
};

}  // namespace marble
