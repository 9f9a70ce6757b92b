#include "marble/core/png_text.h"

#include <array>
#include <cstdint>
#include <stdexcept>

namespace marble {
namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

// CRC-32 as the PNG specification defines it (ISO 3309, polynomial 0xEDB88320, reflected).
uint32_t crc32(std::string_view a, std::string_view b) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (std::string_view part : {a, b})
    for (unsigned char ch : part) c = table[(c ^ ch) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

uint32_t readU32(std::string_view s, size_t at) {
  return (uint32_t(uint8_t(s[at])) << 24) | (uint32_t(uint8_t(s[at + 1])) << 16) | (uint32_t(uint8_t(s[at + 2])) << 8) |
         uint32_t(uint8_t(s[at + 3]));
}

void appendU32(std::string& s, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>((v >> shift) & 0xFF));
}

struct Chunk {
  std::string_view type, data;
  size_t end;  // offset after its CRC
};

// The chunk at `at`; throws when it runs past the end or its CRC is wrong.
Chunk chunkAt(std::string_view png, size_t at) {
  if (png.size() - at < 12) throw std::invalid_argument("truncated chunk");
  const uint32_t length = readU32(png, at);
  if (length > png.size() - at - 12) throw std::invalid_argument("a chunk runs past the end of the file");
  Chunk c{png.substr(at + 4, 4), png.substr(at + 8, length), at + 12 + length};
  if (crc32(c.type, c.data) != readU32(png, at + 8 + length))
    throw std::invalid_argument("chunk " + std::string(c.type) + ": bad CRC");
  return c;
}

void checkSignature(std::string_view png) {
  if (png.substr(0, 8) != kSignature) throw std::invalid_argument("not a PNG file");
}

}  // namespace

std::string insertPngText(std::string_view png, const std::string& keyword, std::string_view text) {
  checkSignature(png);
  if (keyword.empty() || keyword.size() > 79 || keyword.find('\0') != std::string::npos)
    throw std::invalid_argument("PNG text keyword must be 1-79 characters");
  const Chunk ihdr = chunkAt(png, kSignature.size());
  if (ihdr.type != "IHDR") throw std::invalid_argument("the first chunk is not IHDR");
  // iTXt: keyword, 0, compression flag 0, method 0, language tag "", 0, translated keyword "", 0, text.
  std::string data = keyword;
  data.append(std::string_view("\0\0\0\0\0", 5));
  data.append(text);
  if (data.size() > 0x7FFFFFFFu) throw std::invalid_argument("PNG text too long");
  std::string out(png.substr(0, ihdr.end));
  appendU32(out, static_cast<uint32_t>(data.size()));
  out += "iTXt";
  out += data;
  appendU32(out, crc32("iTXt", data));
  out.append(png.substr(ihdr.end));
  return out;
}

std::optional<std::string> findPngText(std::string_view png, const std::string& keyword) {
  checkSignature(png);
  for (size_t at = kSignature.size(); at < png.size();) {
    const Chunk c = chunkAt(png, at);
    at = c.end;
    if (c.type == "IEND") break;
    if (c.type != "tEXt" && c.type != "iTXt") continue;
    const size_t nul = c.data.find('\0');
    if (nul == std::string_view::npos || c.data.substr(0, nul) != keyword) continue;
    std::string_view rest = c.data.substr(nul + 1);
    if (c.type == "tEXt") return std::string(rest);  // Latin-1; marble writes iTXt, so this is someone else's
    if (rest.size() < 2) throw std::invalid_argument("iTXt chunk too short");
    if (rest[0] != 0) throw std::invalid_argument("iTXt chunk " + keyword + " is compressed (not supported)");
    rest = rest.substr(2);
    for (int field = 0; field < 2; ++field) {  // language tag, translated keyword
      const size_t end = rest.find('\0');
      if (end == std::string_view::npos) throw std::invalid_argument("iTXt chunk cut short");
      rest = rest.substr(end + 1);
    }
    return std::string(rest);
  }
  return std::nullopt;
}

}  // namespace marble
