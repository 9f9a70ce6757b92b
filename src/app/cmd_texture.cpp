#include "cmd_texture.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <thread>

#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/noise/marble_pattern.h"
#include "marble/scene/material_io.h"
#include "image_set_output.h"
#include "scene_options.h"
#include "texture_slice.h"

namespace marble {
namespace {

constexpr int kMinSize = 8;
constexpr int kMaxSize = 8192;

uint8_t toByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// Linear -> sRGB transfer (IEC 61966-2-1), for the coloured image only: the grey stages are
// data, written as the paper does (value * 255).
float linearToSrgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

ImageRGBA8 blank(int size) {
  ImageRGBA8 img;
  img.width = img.height = size;
  img.pixels.assign(static_cast<size_t>(size) * size * 4, 255);
  return img;
}

void putGrey(ImageRGBA8& img, int x, int y, float v) {
  uint8_t* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * 4];
  p[0] = p[1] = p[2] = toByte(v);
}

// The paper's texture repeats exactly when every octave's lattice wraps with the texture (octave
// sizes dividing the resolution: turb_size a power of two dividing it) and the sine's ramp
// advances by whole periods across it (x_period, y_period whole numbers).
void checkPaperTiles(const Material& m) {
  const float s = m.turb_size;
  const bool powerOfTwo = s >= 1.0f && s == std::floor(s) && (static_cast<uint32_t>(s) & (static_cast<uint32_t>(s) - 1u)) == 0u;
  if (!powerOfTwo || m.resolution % static_cast<int>(s) != 0)
    throw InputError("--tile", "turb_size", "the paper's texture tiles only when turb_size is a power of two dividing the resolution");
  if (m.x_period != std::floor(m.x_period) || m.y_period != std::floor(m.y_period))
    throw InputError("--tile", "x_period/y_period", "the paper's texture tiles only with whole-number periods");
}

}  // namespace

int runTextureCommand(const TextureOptions& options) {
  return reportErrors("texture", [&] {
    if (options.out_dir.empty()) throw InputError("-o", "", "an output folder is required");
    if (options.size < kMinSize || options.size > kMaxSize)
      throw InputError("--size", "", "expected a whole number in [" + std::to_string(kMinSize) + ", " +
                                         std::to_string(kMaxSize) + "], got " + std::to_string(options.size));
    Material m = loadPreset(options.preset);
    for (const auto& kv : options.sets) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) throw InputError("--set", kv, "expected key=value");
      setMaterialKey(m, kv.substr(0, eq), kv.substr(eq + 1));
    }
    std::error_code ec;
    std::filesystem::create_directories(options.out_dir, ec);
    if (ec || !std::filesystem::is_directory(options.out_dir))
      throw InputError(options.out_dir.string(), "", "cannot create folder" + (ec ? ": " + ec.message() : std::string()));

    if (m.vein_model != VeinModel::Paper) {
      const SliceSpec slice = parseSlice(options.slice.empty() ? "z=0" : options.slice);
      const SliceImages images = renderVeinSlice(m, slice, options.size, options.tile);
      writeImageSet(options.out_dir, {{"marble.png", &images.marble}, {"veins.png", &images.veins}});
      return 0;
    }
    if (!options.slice.empty())
      throw InputError("--slice", options.slice, "slices are of the vein models (vein_model network or breccia); the paper's texture is 2D");
    if (options.tile) checkPaperTiles(m);

    const int n = options.size;
    const float W = static_cast<float>(m.resolution);
    const float texelsPerPixel = W / static_cast<float>(n);
    ImageRGBA8 white, smooth, turb, sine, marble;
    try {
      white = blank(n), smooth = blank(n), turb = blank(n), sine = blank(n), marble = blank(n);
    } catch (const std::bad_alloc&) {
      throw EnvironmentError("--size " + std::to_string(n) + ": out of memory for five " + std::to_string(n) + " x " +
                             std::to_string(n) + " images (" + std::to_string(5ull * n * n * 4 >> 20) + " MiB)");
    }

    // Pixel (x, y) shows texel (x, y) * W / size: the whole W x W texture, row 0 at the top.
    // Smooth noise is shown at the first octave's zoom (turb_size texels per lattice cell).
    auto work = [&](int firstRow, int stride) {
      std::vector<float> xs(static_cast<size_t>(n)), t(static_cast<size_t>(n)), v(static_cast<size_t>(n));
      for (int x = 0; x < n; ++x) xs[static_cast<size_t>(x)] = static_cast<float>(x) * texelsPerPixel;
      for (int y = firstRow; y < n; y += stride) {
        const float qy = static_cast<float>(y) * texelsPerPixel;
        patternRow2(m, xs.data(), qy, n, t.data(), v.data());
        for (int x = 0; x < n; ++x) {
          const glm::vec2 q(xs[static_cast<size_t>(x)], qy);
          putGrey(white, x, y, whiteNoise(m, q));
          putGrey(smooth, x, y, smoothNoise(m, q / m.turb_size));
          putGrey(turb, x, y, t[static_cast<size_t>(x)]);
          putGrey(sine, x, y, v[static_cast<size_t>(x)]);
          const glm::vec3 c = patternColor(m, v[static_cast<size_t>(x)]);
          uint8_t* p = &marble.pixels[(static_cast<size_t>(y) * n + x) * 4];
          p[0] = toByte(linearToSrgb(c.x));
          p[1] = toByte(linearToSrgb(c.y));
          p[2] = toByte(linearToSrgb(c.z));
        }
      }
    };
    const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work, i, threads);
    work(0, threads);
    for (auto& th : pool) th.join();

    writeImageSet(options.out_dir, {{"white_noise.png", &white},
                                    {"smooth_noise.png", &smooth},
                                    {"turbulence.png", &turb},
                                    {"sine.png", &sine},
                                    {"marble.png", &marble}});
    return 0;
  });
}

}  // namespace marble
