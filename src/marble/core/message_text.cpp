#include "marble/core/message_text.h"

#include <cstdint>

namespace marble {
namespace {

// Length of the well-formed UTF-8 sequence at `s[i]` (2..4), or 0 when there is none there.
size_t utf8SequenceLength(std::string_view s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  size_t n = 0;
  uint32_t cp = 0;
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
    cp = b & 0x1Fu;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    cp = b & 0x0Fu;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    cp = b & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
  if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  // C1 controls (U+0080..U+009F, e.g. the 8-bit CSI) and the Unicode line/paragraph
  // separators act like control characters on a terminal.
  if ((cp >= 0x80 && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029) return 0;
  return n;
}

void appendHex(std::string& out, unsigned char b) {
  static const char digits[] = "0123456789abcdef";
  out += "\\x";
  out += digits[b >> 4];
  out += digits[b & 15];
}

}  // namespace

std::string printable(std::string_view text, size_t limit) {
  std::string out;
  out.reserve(text.size() < limit ? text.size() : limit);
  size_t i = 0;
  for (; i < text.size(); ) {
    const unsigned char b = static_cast<unsigned char>(text[i]);
    std::string piece;
    size_t used = 1;
    if (b >= 0x20 && b < 0x7F) {
      piece.assign(1, static_cast<char>(b));
    } else if (b == '\n') {
      piece = "\\n";
    } else if (b == '\r') {
      piece = "\\r";
    } else if (b == '\t') {
      piece = "\\t";
    } else if (b == 0) {
      piece = "\\0";
    } else if (b >= 0x80) {
      used = utf8SequenceLength(text, i);
      if (used > 0) {
        piece.assign(text.substr(i, used));
      } else {
        used = 1;
        appendHex(piece, b);
      }
    } else {
      appendHex(piece, b);
    }
    if (out.size() + piece.size() > limit) break;
    out += piece;
    i += used;
  }
  if (i < text.size()) {
    // Cut: room is made for the note so that the result stays within `limit` where it can.
    const std::string note = " ... (" + std::to_string(text.size()) + " bytes in all)";
    size_t keep = limit > note.size() ? limit - note.size() : 0;
    if (out.size() > keep) {
      // Back up to the start of a character or an escape, never into the middle of one.
      size_t cut = keep;
      while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0u) == 0x80u) --cut;
      const size_t backslash = out.rfind('\\', cut);
      if (backslash != std::string::npos && cut - backslash < 4 && cut > backslash) cut = backslash;
      out.resize(cut);
    }
    out += note;
  }
  return out;
}

std::string quotedExcerpt(std::string_view text, size_t limit) {
  std::string body = printable(text.substr(0, limit), limit * 4);
  return "\"" + body + (text.size() > limit ? "...\"" : "\"");
}

}  // namespace marble
