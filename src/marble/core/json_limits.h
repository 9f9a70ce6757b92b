#pragma once
// Bounds on what a JSON file (scene, preset, glTF) may make marble do. nlohmann's parser keeps
// its own stack, but a value nested 100,000 deep is still destroyed, compared and printed
// recursively; so the nesting is checked on the text before it is parsed. Values quoted in
// messages are excerpts built with a budget, never a full dump of a value that may be megabytes.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace marble {

// Deeper than any scene, preset or glTF needs (they use at most about 6 levels).
inline constexpr size_t kMaxJsonDepth = 64;

// Throws InputError(file, "line L, column C", "JSON nested deeper than 64 levels ...") when
// arrays and objects nest deeper than kMaxJsonDepth. Brackets inside strings do not count.
void checkJsonNesting(std::string_view text, const std::string& file);

// nlohmann's message for a parse error without its "[json.exception...] " prefix and without
// the "; last read: '...'" part, which quotes the file's content (a credential file named as a
// preset must not reach the terminal): "parse error at line 1, column 2: syntax error while
// parsing value - invalid literal".
std::string jsonErrorText(const std::string& what);

// A short, one-line rendering of `value` for a message: its JSON text cut to about `limit`
// characters ("[1,2,3,...]" ), built without serializing more than that.
std::string jsonExcerpt(const nlohmann::json& value, size_t limit = 40);

}  // namespace marble
