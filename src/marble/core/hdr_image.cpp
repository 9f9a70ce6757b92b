#include "marble/core/hdr_image.h"

#include <stb_image.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

#include "marble/core/error.h"
#include "marble/core/input_file.h"

namespace marble {
namespace {

// The header is a few lines of text; a file whose header runs past this is not a Radiance image.
constexpr size_t kMaxHeaderBytes = 64 * 1024;


std::string withThousands(unsigned long long n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string quoted(std::string_view line) {
  std::string s(line.substr(0, 60));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return "\"" + s + (line.size() > 60 ? "...\"" : "\"");
}

// Opens the map through the one input-file routine (regular files only) and refuses an empty one.
InputFile openMap(const std::filesystem::path& path, const std::string& file) {
  InputFile in(path, file, "an image file");
  if (in.size() == 0) throw InputError(file, "", "file is empty");
  return in;
}

// A positive decimal that fits an int, e.g. the "512" of "-Y 512".
bool parseSide(std::string_view& text, int& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec != std::errc() || end == text.data()) return false;
  text.remove_prefix(static_cast<size_t>(end - text.data()));
  return true;
}

// Walks the run-length encoded scanlines the way stb_image decodes them, without decoding, so
// that stb is only handed complete, well-formed data: at the end of its input stb returns zero
// bytes forever, and a zero count never advances its scanline loop (a truncated file would
// hang it); a later scanline without the RLE marker makes it restart in flat mode from the top.
void checkRunLengthScanlines(const std::string& file, const std::string& data, size_t pos, int width, int height) {
  const size_t size = data.size();
  const auto at = [&](size_t i) { return static_cast<unsigned char>(data[i]); };
  for (int row = 0; row < height; ++row) {
    const std::string place = "pixel data, row " + std::to_string(row) + " of " + std::to_string(height);
    const auto truncated = [&] { throw InputError(file, place, "the file ends inside the scanline (truncated)"); };
    if (pos + 4 > size) truncated();
    if (at(pos) != 2 || at(pos + 1) != 2 || (at(pos + 2) & 0x80))
      throw InputError(file, place, "no run-length marker (2 2 hi lo) where the scanline should start (corrupt)");
    const int length = at(pos + 2) << 8 | at(pos + 3);
    if (length != width)
      throw InputError(file, place, "the scanline says it is " + std::to_string(length) + " pixels wide, the image " +
                                        std::to_string(width) + " (corrupt)");
    pos += 4;
    for (int channel = 0; channel < 4; ++channel)
      for (int x = 0; x < width;) {
        if (pos >= size) truncated();
        const int count = at(pos++);
        const bool run = count > 128;
        const int n = run ? count - 128 : count;
        if (n > width - x)
          throw InputError(file, place, "a run of " + std::to_string(n) + " pixels goes past the scanline's end (corrupt)");
        const size_t bytes = run ? 1 : static_cast<size_t>(n);
        if (pos + bytes > size) truncated();
        pos += bytes;
        x += n;
      }
  }
}

}  // namespace

HdrHeader readHdrHeader(const std::filesystem::path& path) {
  const std::string file = path.string();
  const InputFile in = openMap(path, file);
  const unsigned long long size = in.size();
  std::string head = in.readPrefix(static_cast<size_t>(std::min<unsigned long long>(size, kMaxHeaderBytes)));

  // Lines of the header: the signature, variables (FORMAT=...), an empty line, the resolution.
  size_t pos = 0;
  int lineNumber = 0;
  auto nextLine = [&](std::string_view& line) {
    const size_t nl = head.find('\n', pos);
    if (nl == std::string::npos) return false;
    line = std::string_view(head).substr(pos, nl - pos);
    pos = nl + 1;
    ++lineNumber;
    return true;
  };
  std::string_view line;
  const bool hasFirstLine = nextLine(line);
  // stb_image accepts exactly these two signatures.
  if (!hasFirstLine || (line != "#?RADIANCE" && line != "#?RGBE"))
    throw InputError(file, "", "not a Radiance .hdr file (it must start with the line #?RADIANCE or #?RGBE)");
  bool rgbe = false;
  for (;;) {
    if (!nextLine(line))
      throw InputError(file, "header", "no end of header (an empty line) in the first " +
                                           withThousands(head.size()) + " bytes (truncated?)");
    if (line.empty()) break;
    if (line.rfind("FORMAT=", 0) == 0) {
      if (line != "FORMAT=32-bit_rle_rgbe")
        throw InputError(file, "header line " + std::to_string(lineNumber),
                         quoted(line) + " is not supported (only FORMAT=32-bit_rle_rgbe)");
      rgbe = true;
    }
  }
  if (!rgbe) throw InputError(file, "header", "no FORMAT=32-bit_rle_rgbe line");
  if (!nextLine(line)) throw InputError(file, "header", "no resolution line after the header (truncated?)");
  const std::string place = "header line " + std::to_string(lineNumber);
  HdrHeader h;
  // "-Y height +X width": rows top to bottom, pixels left to right (what stb_image reads).
  const auto resolution = [&h](std::string_view text) {
    const auto skipSpaces = [&text] {
      while (!text.empty() && (text.front() == ' ' || text.front() == '\r')) text.remove_prefix(1);
    };
    const auto word = [&text](std::string_view w) { return text.rfind(w, 0) == 0 && (text.remove_prefix(w.size()), true); };
    if (!word("-Y ")) return false;
    skipSpaces();
    if (!parseSide(text, h.height)) return false;
    skipSpaces();
    if (!word("+X ")) return false;
    skipSpaces();
    if (!parseSide(text, h.width)) return false;
    skipSpaces();
    return text.empty();
  };
  if (!resolution(line))
    throw InputError(file, place, "resolution " + quoted(line) + " is not supported (only \"-Y height +X width\", top row first)");
  if (h.width < 1 || h.height < 1)
    throw InputError(file, place, "image is " + std::to_string(h.width) + " x " + std::to_string(h.height) + " pixels");
  if (h.width > kMaxHdrSide || h.height > kMaxHdrSide)
    throw InputError(file, place, "image is " + withThousands(static_cast<unsigned long long>(h.width)) + " x " +
                                      withThousands(static_cast<unsigned long long>(h.height)) +
                                      " pixels; the limit is " + withThousands(kMaxHdrSide) + " per side");
  h.dataOffset = static_cast<long long>(pos);

  // Scanlines 8 to 32767 wide may be run-length encoded, marked by the bytes 2 2 hi lo (lo, hi
  // < 128); otherwise the pixels are flat RGBE quadruples (the rule stb_image follows).
  const unsigned long long dataBytes = size - pos;
  if (dataBytes == 0) throw InputError(file, "", "no pixel data after the header (truncated?)");
  if (head.size() < pos + 4 && size > head.size()) head = in.readPrefix(pos + 4);
  const auto byte = [&](size_t i) { return pos + i < head.size() ? static_cast<unsigned char>(head[pos + i]) : 0u; };
  h.runLengthEncoded = h.width >= 8 && h.width < 32768 && byte(0) == 2 && byte(1) == 2 && byte(2) < 128;
  // The least the pixels can take, checked before the decoder allocates for them: flat pixels
  // take 4 bytes each; a run-length encoded scanline takes its 4-byte marker and, per channel,
  // at least 2 bytes per 127 pixels (the longest run).
  const auto w = static_cast<unsigned long long>(h.width), ht = static_cast<unsigned long long>(h.height);
  const unsigned long long need = h.runLengthEncoded ? ht * (4 + 4 * 2 * ((w + 126) / 127)) : 4 * w * ht;
  if (dataBytes < need)
    throw InputError(file, "", "truncated: " + std::to_string(h.width) + " x " + std::to_string(h.height) +
                                   (h.runLengthEncoded ? " run-length encoded pixels need at least " : " flat RGBE pixels need ") +
                                   withThousands(need) + " bytes but " + withThousands(dataBytes) + " follow the header");
  return h;
}

ImageRGBF readHdr(const std::filesystem::path& path) {
  const std::string file = path.string();
  const HdrHeader header = readHdrHeader(path);  // every check that needs no pixel memory
  // The most valid pixel data can take (all RLE literal dumps); anything after it is ignored.
  const auto w = static_cast<unsigned long long>(header.width), h = static_cast<unsigned long long>(header.height);
  const unsigned long long most = static_cast<unsigned long long>(header.dataOffset) + h * (4 + 4 * (w + (w + 127) / 128));
  const InputFile in = openMap(path, file);
  std::string data = in.readPrefix(static_cast<size_t>(std::min<unsigned long long>(in.size(), most)));
  if (header.runLengthEncoded)
    checkRunLengthScanlines(file, data, static_cast<size_t>(header.dataOffset), header.width, header.height);
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(data.data()), static_cast<int>(data.size()), &width,
                             &height, &channels, 3),
      stbi_image_free);
  if (!pixels) {
    const char* why = stbi_failure_reason();
    throw InputError(file, "pixel data", std::string("cannot decode: ") + (why ? why : "unknown error"));
  }
  { std::string().swap(data); }
  if (width != header.width || height != header.height)
    throw InputError(file, "", "decoded " + std::to_string(width) + " x " + std::to_string(height) +
                                   " pixels, the header says " + std::to_string(header.width) + " x " +
                                   std::to_string(header.height));
  ImageRGBF img{width, height, std::vector<float>(pixels.get(), pixels.get() + static_cast<size_t>(width) * height * 3)};
  pixels.reset();
  // RGBE cannot encode a NaN or an infinity (its largest value is about 1.7e38), so this only
  // guards against a decoder surprise; the renderer relies on finite radiance.
  for (size_t i = 0; i < img.pixels.size(); ++i)
    if (!std::isfinite(img.pixels[i])) {
      const size_t p = i / 3, wide = static_cast<size_t>(width);
      throw InputError(file, "pixel (" + std::to_string(p % wide) + ", " + std::to_string(p / wide) + ")",
                       "value is not a finite number");
    }
  return img;
}

}  // namespace marble
