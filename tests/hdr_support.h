#pragma once
// Radiance .hdr files made by the tests themselves (the project ships no .hdr assets): a minimal
// RGBE writer, flat or run-length encoded (Ward, "Real Pixels", Graphics Gems II, 1991; the
// scanline RLE of Radiance's color.c format), and a synthetic sky to light things with.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <glm/glm.hpp>

#include "marble/core/image.h"
#include "marble/environment/equirect.h"

namespace marble::test {

// One pixel as R, G, B mantissas sharing the exponent E (value = mantissa 2^(E - 136)).
inline void rgbeBytes(const float* rgb, unsigned char out[4]) {
  const float v = std::max({rgb[0], rgb[1], rgb[2]});
  if (v < 1e-32f) {
    out[0] = out[1] = out[2] = out[3] = 0;
    return;
  }
  int e = 0;
  const float scale = std::frexp(v, &e) * 256.0f / v;
  for (int c = 0; c < 3; ++c) out[c] = static_cast<unsigned char>(std::max(rgb[c], 0.0f) * scale);
  out[3] = static_cast<unsigned char>(e + 128);
}

// One channel of one scanline: runs of 3 or more equal bytes as (128 + n, byte), the rest as
// literal dumps of up to 128 bytes (n, bytes...).
inline void appendRunLength(std::string& out, const unsigned char* bytes, int n) {
  int i = 0;
  while (i < n) {
    int run = 1;
    while (i + run < n && run < 127 && bytes[i + run] == bytes[i]) ++run;
    if (run >= 3) {
      out += static_cast<char>(128 + run);
      out += static_cast<char>(bytes[i]);
      i += run;
      continue;
    }
    int j = i;
    while (j < n && j - i < 128 && !(j + 2 < n && bytes[j] == bytes[j + 1] && bytes[j] == bytes[j + 2])) ++j;
    out += static_cast<char>(j - i);
    out.append(reinterpret_cast<const char*>(bytes + i), static_cast<size_t>(j - i));
    i = j;
  }
}

inline std::string hdrHeader(int width, int height) {
  return "#?RADIANCE\n# made by the marble tests\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " +
         std::to_string(width) + "\n";
}

// The whole file. Run-length encoding needs 8 <= width < 32768 (the format's rule).
inline std::string encodeHdr(const ImageRGBF& img, bool runLength = true) {
  std::string out = hdrHeader(img.width, img.height);
  const bool rle = runLength && img.width >= 8 && img.width < 32768;
  std::string channels[4];
  for (int y = 0; y < img.height; ++y) {
    for (auto& c : channels) c.assign(static_cast<size_t>(img.width), '\0');
    for (int x = 0; x < img.width; ++x) {
      unsigned char px[4];
      rgbeBytes(&img.pixels[(static_cast<size_t>(y) * img.width + x) * 3], px);
      if (!rle) out.append(reinterpret_cast<const char*>(px), 4);
      for (int c = 0; c < 4; ++c) channels[c][static_cast<size_t>(x)] = static_cast<char>(px[c]);
    }
    if (!rle) continue;
    out += '\x02';
    out += '\x02';
    out += static_cast<char>(img.width >> 8);
    out += static_cast<char>(img.width & 0xFF);
    for (const auto& c : channels)
      appendRunLength(out, reinterpret_cast<const unsigned char*>(c.data()), img.width);
  }
  return out;
}

inline void writeHdrFile(const std::filesystem::path& path, const ImageRGBF& img, bool runLength = true) {
  std::ofstream(path, std::ios::binary) << encodeHdr(img, runLength);
}

inline ImageRGBF constantImage(int width, int height, const glm::vec3& rgb) {
  ImageRGBF img{width, height, std::vector<float>(static_cast<size_t>(width) * height * 3)};
  for (size_t i = 0; i < img.pixels.size(); i += 3) {
    img.pixels[i] = rgb.r;
    img.pixels[i + 1] = rgb.g;
    img.pixels[i + 2] = rgb.b;
  }
  return img;
}

// Fills every texel from its direction (equirect.h's mapping).
template <typename F>
ImageRGBF imageFromDirections(int width, int height, F radiance) {
  ImageRGBF img{width, height, std::vector<float>(static_cast<size_t>(width) * height * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 c = radiance(equirectDirection((x + 0.5) / width, (y + 0.5) / height));
      float* p = &img.pixels[(static_cast<size_t>(y) * width + x) * 3];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  return img;
}

// An outdoor-ish light for looking at reflections: a blue sky brightening to the horizon, a
// small sun 5000 times brighter than the sky (up 35 degrees, front right: azimuth -Z turned
// 40 degrees towards +X), a warm orange wall on the left (-X), a green panel behind (+Z) and a
// grey-brown ground. (Directions in marble's world: +Y up, the default camera looks along -Z.)
inline ImageRGBF syntheticSky(int width) {
  const glm::vec3 sun = glm::normalize(glm::vec3(std::sin(glm::radians(40.0f)) * std::cos(glm::radians(35.0f)),
                                                 std::sin(glm::radians(35.0f)),
                                                 -std::cos(glm::radians(40.0f)) * std::cos(glm::radians(35.0f))));
  const float sunCos = std::cos(glm::radians(1.5f));
  return imageFromDirections(width, width / 2, [&](const glm::vec3& d) {
    if (glm::dot(d, sun) > sunCos) return glm::vec3(5000.0f, 4700.0f, 4200.0f);
    const float az = std::atan2(d.x, -d.z);  // 0 ahead (-Z), +90 degrees right (+X)
    const float el = std::asin(std::clamp(d.y, -1.0f, 1.0f));
    if (el > -0.05f && el < 0.6f && az < glm::radians(-60.0f) && az > glm::radians(-130.0f))
      return glm::vec3(1.6f, 0.45f, 0.08f);  // the orange wall
    if (el > 0.0f && el < 0.45f && std::abs(az) > glm::radians(150.0f)) return glm::vec3(0.1f, 0.9f, 0.2f);  // green panel
    if (d.y < 0.0f) return glm::vec3(0.22f, 0.19f, 0.16f);                                                  // ground
    const float t = std::pow(1.0f - d.y, 3.0f);
    return glm::mix(glm::vec3(0.18f, 0.35f, 0.85f), glm::vec3(0.85f, 0.9f, 1.0f), t);  // zenith to horizon
  });
}

}  // namespace marble::test
