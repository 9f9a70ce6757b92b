#pragma once
// PNG text chunks in and out of an encoded PNG (bytes in memory): the chunk layout, the CRC.
// stb_image_write writes none and stb_image reads none, so marble inserts and finds them.
#include <optional>
#include <string>
#include <string_view>

namespace marble {

// Inserts an uncompressed iTXt chunk (keyword, UTF-8 text) right after IHDR. Throws
// std::invalid_argument for a malformed PNG or keyword.
std::string insertPngText(std::string_view png, const std::string& keyword, std::string_view text);

// The first tEXt or uncompressed iTXt chunk named `keyword`; nothing when absent. A malformed
// file (not a PNG, a chunk running past the end, a bad CRC) throws std::invalid_argument with
// the problem.
std::optional<std::string> findPngText(std::string_view png, const std::string& keyword);

}  // namespace marble
