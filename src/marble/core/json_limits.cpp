#include "marble/core/json_limits.h"

#include "marble/core/error.h"
#include "marble/core/message_text.h"

namespace marble {

void checkJsonNesting(std::string_view text, const std::string& file) {
  size_t depth = 0, line = 1, lineStart = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;  // the escaped character cannot end the string
      else if (c == '"') inString = false;
      continue;
    }
    switch (c) {
      case '"': inString = true; break;
      case '\n':
        ++line;
        lineStart = i + 1;
        break;
      case '[':
      case '{':
        if (++depth > kMaxJsonDepth)
          throw InputError(file, "line " + std::to_string(line) + ", column " + std::to_string(i - lineStart + 1),
                           "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (arrays and objects); "
                           "no scene, preset or glTF needs that many");
        break;
      case ']':
      case '}':
        if (depth > 0) --depth;  // unbalanced brackets are the parser's to report
        break;
      default: break;
    }
  }
}

std::string jsonErrorText(const std::string& what) {
  std::string text = what;
  if (const size_t bracket = text.find("] "); text.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos)
    text.erase(0, bracket + 2);
  if (const size_t lastRead = text.find("; last read: "); lastRead != std::string::npos) {
    const size_t expected = text.find("'; expected ", lastRead);
    text.erase(lastRead, expected == std::string::npos ? std::string::npos : expected + 1 - lastRead);
  }
  return text;
}

namespace {

// Appends `v`'s JSON text to `out` until `out` reaches `limit`; returns false once it did.
bool appendExcerpt(const nlohmann::json& v, std::string& out, size_t limit, int depth) {
  if (out.size() >= limit) return false;
  if (v.is_array() || v.is_object()) {
    const bool array = v.is_array();
    out += array ? '[' : '{';
    if (depth > 8) {  // the budget ends long before; this only caps the recursion
      out += "...";
      return false;
    }
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (!first) out += ',';
      first = false;
      if (!array) {
        out += nlohmann::json(it.key()).dump();
        out += ':';
      }
      if (!appendExcerpt(it.value(), out, limit, depth + 1)) return false;
      if (out.size() >= limit) return false;
    }
    out += array ? ']' : '}';
    return true;
  }
  if (v.is_string()) {
    // Only the head of a long string is serialized: "AAAA...".
    const auto& s = v.get_ref<const std::string&>();
    const size_t room = limit > out.size() + 2 ? limit - out.size() - 2 : 0;
    std::string text = nlohmann::json(s.substr(0, room)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (s.size() <= room) {
      out += text;
      return true;
    }
    text.pop_back();  // the closing quote
    out += text + "...\"";
    return false;
  }
  out += v.dump();
  return true;
}

}  // namespace

std::string jsonExcerpt(const nlohmann::json& value, size_t limit) {
  std::string out;
  const bool whole = appendExcerpt(value, out, limit, 0);
  const bool marked = out.size() >= 4 && out.compare(out.size() - 4, 4, "...\"") == 0;
  if ((!whole && !marked) || out.size() > limit + 4) {
    if (out.size() > limit) out.resize(limit);
    out += "...";
  }
  return printable(out, limit + 40);
}

}  // namespace marble
