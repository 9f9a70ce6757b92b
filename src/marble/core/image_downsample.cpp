#include "marble/core/image_downsample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace marble {
namespace {

void checkFactor(int width, int height, int factor) {
  if (factor < 1 || width % factor != 0 || height % factor != 0)
    throw std::invalid_argument("downsample: " + std::to_string(width) + "x" + std::to_string(height) +
                                " is not a multiple of " + std::to_string(factor));
}

// sRGB EOTF and its inverse (IEC 61966-2-1); the 256 decoded values are computed once.
const std::array<float, 256>& srgbToLinearTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = static_cast<float>(i) / 255.0f;
      t[static_cast<size_t>(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table;
}

uint8_t linearToSrgbByte(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  const float e = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(e * 255.0f));
}

// Sums each factor x factor block of `channels`-component pixels through `load`, hands the block's
// mean to `store`.
template <typename Load, typename Store>
void boxFilter(int width, int height, int channels, int factor, Load load, Store store) {
  const int outWidth = width / factor, outHeight = height / factor;
  const float norm = 1.0f / static_cast<float>(factor * factor);
  std::vector<float> sum(static_cast<size_t>(channels));
  for (int y = 0; y < outHeight; ++y)
    for (int x = 0; x < outWidth; ++x) {
      std::fill(sum.begin(), sum.end(), 0.0f);
      for (int by = 0; by < factor; ++by)
        for (int bx = 0; bx < factor; ++bx) {
          const size_t src = (static_cast<size_t>(y * factor + by) * width + static_cast<size_t>(x * factor + bx)) * channels;
          for (int c = 0; c < channels; ++c) sum[static_cast<size_t>(c)] += load(src + static_cast<size_t>(c), c);
        }
      const size_t dst = (static_cast<size_t>(y) * outWidth + static_cast<size_t>(x)) * channels;
      for (int c = 0; c < channels; ++c) store(dst + static_cast<size_t>(c), c, sum[static_cast<size_t>(c)] * norm);
    }
}

}  // namespace

ImageRGBA8 downsampleSrgb(const ImageRGBA8& image, int factor) {
  checkFactor(image.width, image.height, factor);
  ImageRGBA8 out{image.width / factor, image.height / factor, {}};
  out.pixels.resize(static_cast<size_t>(out.width) * out.height * 4);
  const auto& decode = srgbToLinearTable();
  boxFilter(
      image.width, image.height, 4, factor,
      [&](size_t i, int c) { return c == 3 ? static_cast<float>(image.pixels[i]) / 255.0f : decode[image.pixels[i]]; },
      [&](size_t i, int c, float v) {
        out.pixels[i] = c == 3 ? static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)) : linearToSrgbByte(v);
      });
  return out;
}

ImageRGBF downsampleLinear(const ImageRGBF& image, int factor) {
  checkFactor(image.width, image.height, factor);
  ImageRGBF out{image.width / factor, image.height / factor, {}};
  out.pixels.resize(static_cast<size_t>(out.width) * out.height * 3);
  boxFilter(
      image.width, image.height, 3, factor, [&](size_t i, int) { return image.pixels[i]; },
      [&](size_t i, int, float v) { out.pixels[i] = v; });
  if (!image.alpha.empty()) {  // coverage averages too: a block half on the object is half covered
    out.alpha.resize(static_cast<size_t>(out.width) * out.height);
    boxFilter(
        image.width, image.height, 1, factor, [&](size_t i, int) { return image.alpha[i]; },
        [&](size_t i, int, float v) { out.alpha[i] = v; });
  }
  return out;
}

}  // namespace marble
