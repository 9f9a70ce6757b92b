#pragma once
// Images in memory and on disk. PNG output is 8-bit sRGB-encoded (the caller encodes),
// written atomically.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace marble {

struct ImageRGBA8 {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // row 0 is the top row
  glm::u8vec4 at(int x, int y) const {
    const uint8_t* p = &pixels[(static_cast<size_t>(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
};

struct ImageRGBF {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB, linear, row 0 is the top row
  // Coverage, width * height values in [0, 1] (1: the object, 0: background), row 0 the top
  // row; empty when the image has no alpha channel.
  std::vector<float> alpha = {};
};

// The file's bytes, for writing several files together (AtomicFileSet, core/atomic_file.h) or
// embedding in a .glb. Deterministic.
std::string encodePng(const ImageRGBA8& image);
std::string encodeExr(const ImageRGBF& image);

// A text chunk of a PNG file: a keyword (1-79 printable Latin-1 characters) and UTF-8 text,
// written as an uncompressed iTXt chunk (PNG specification, 11.3.4.5).
struct PngText {
  std::string keyword;
  std::string text;
};

// `text` chunks go before the image data, where a reader finds them without decoding it.
void writePng(const std::filesystem::path& path, const ImageRGBA8& image,
              const std::vector<PngText>& text = {});          // throws InputError
ImageRGBA8 readPng(const std::filesystem::path& path);       // throws InputError
// The text of the first tEXt or uncompressed iTXt chunk named `keyword`, or nothing. Throws
// InputError naming the file when it cannot be read or is not a PNG.
std::optional<std::string> readPngText(const std::filesystem::path& path, const std::string& keyword);
// Linear half-float RGBA; A is image.alpha (1 everywhere when it is empty). A file written with
// alpha says so in its header (kExrCoverageAttribute), so that a reader can tell coverage that
// happens to be 1 everywhere from an alpha channel that means nothing.
void writeExr(const std::filesystem::path& path, const ImageRGBF& image);
// Reads RGB and, when the file has an A channel, alpha; `markedCoverage` (if given) is set to
// whether the header carries the mark. Throws InputError naming the file.
ImageRGBF readExr(const std::filesystem::path& path, bool* markedCoverage = nullptr);
inline constexpr const char* kExrCoverageAttribute = "marbleAlpha";  // its value: "coverage"

// Flips rows (GL reads bottom-up).
void flipRows(ImageRGBA8& image);

}  // namespace marble
