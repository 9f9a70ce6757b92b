#pragma once
// Images in memory and on disk. PNG output is 8-bit sRGB-encoded (the caller encodes),
// written atomically.
#include <cstdint>
#include <filesystem>
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
};

void writePng(const std::filesystem::path& path, const ImageRGBA8& image);  // throws InputError
ImageRGBA8 readPng(const std::filesystem::path& path);                     // throws InputError
void writeExr(const std::filesystem::path& path, const ImageRGBF& image);  // linear half-float RGB
ImageRGBF readExr(const std::filesystem::path& path);

// Flips rows (GL reads bottom-up).
void flipRows(ImageRGBA8& image);

}  // namespace marble
