#pragma once
// Images in memory and on disk. PNG output is 8-bit sRGB-encoded (the caller encodes),
// written atomically.
#include <cstdint>
#include <filesystem>
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

void writePng(const std::filesystem::path& path, const ImageRGBA8& image);  // throws InputError
ImageRGBA8 readPng(const std::filesystem::path& path);                     // throws InputError
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
