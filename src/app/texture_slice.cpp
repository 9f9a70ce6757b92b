#include "texture_slice.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <thread>
#include <vector>

#include "marble/core/error.h"
#include "marble/noise/marble_pattern.h"

namespace marble {
namespace {

uint8_t toByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

float linearToSrgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// The cross-fade weight of the copy one tile on: 0 before the band, 1 at the far edge (smooth).
float bandWeight(float s) {
  const float u = std::clamp((s - (1.0f - kTileBand)) / kTileBand, 0.0f, 1.0f);
  return u * u * (3.0f - 2.0f * u);
}

}  // namespace

SliceSpec parseSlice(const std::string& text) {
  const auto fail = [&](const std::string& problem) -> SliceSpec { throw InputError("--slice", text, problem); };
  if (text.size() < 3 || text[1] != '=' || (text[0] != 'x' && text[0] != 'y' && text[0] != 'z'))
    return fail("expected AXIS=OFFSET with AXIS x, y or z (e.g. z=0.25)");
  SliceSpec s;
  s.axis = text[0] - 'x';
  const char* b = text.data() + 2;
  const char* e = text.data() + text.size();
  double d = 0;
  const auto r = std::from_chars(b, e, d);
  if (r.ec != std::errc() || r.ptr != e || !std::isfinite(d) || d < -1e3 || d > 1e3)
    return fail("expected an offset in [-1000, 1000] object units after '='");
  s.offset = static_cast<float>(d);
  return s;
}

glm::vec3 slicePoint(const SliceSpec& slice, float s, float t) {
  const float u = -1.0f + 2.0f * s;  // right
  const float v = 1.0f - 2.0f * t;   // up
  if (slice.axis == 0) return {slice.offset, v, u};
  if (slice.axis == 1) return {u, slice.offset, -v};
  return {u, v, slice.offset};
}

SliceImages renderVeinSlice(const Material& m, const SliceSpec& slice, int size, bool tile) {
  SliceImages out;
  for (ImageRGBA8* img : {&out.marble, &out.veins}) {
    img->width = img->height = size;
    img->pixels.assign(static_cast<size_t>(size) * size * 4, 255);
  }
  const float inv = 1.0f / static_cast<float>(size);
  // One row of the slice at t, shifted by (ds, dt) slice widths: colours and values.
  auto row = [&](float t, float ds, float dt, std::vector<glm::vec3>& c, std::vector<float>& v) {
    const glm::vec3 origin = slicePoint(slice, 0.5f * inv + ds, t + dt);
    const glm::vec3 step = slicePoint(slice, 1.5f * inv + ds, t + dt) - origin;
    // Rows along x (normals y, z) take the batched path; the step must then be exactly along x.
    const glm::vec3 exactStep = slice.axis == 0 ? step : glm::vec3(step.x, 0.0f, 0.0f);
    veinAlbedoRow(m, origin, exactStep, size, c.data(), v.data());
  };
  auto work = [&](int first, int stride) {
    const size_t n = static_cast<size_t>(size);
    std::vector<glm::vec3> c[4] = {std::vector<glm::vec3>(n), std::vector<glm::vec3>(n), std::vector<glm::vec3>(n),
                                   std::vector<glm::vec3>(n)};
    std::vector<float> v[4] = {std::vector<float>(n), std::vector<float>(n), std::vector<float>(n),
                               std::vector<float>(n)};
    for (int y = first; y < size; y += stride) {
      const float t = (static_cast<float>(y) + 0.5f) * inv;
      row(t, 0.0f, 0.0f, c[0], v[0]);
      const float b = tile ? bandWeight(t) : 0.0f;
      if (tile) {
        row(t, -1.0f, 0.0f, c[1], v[1]);  // the copy to the right continues the left edge
        if (b > 0.0f) {
          row(t, 0.0f, -1.0f, c[2], v[2]);  // the copy below continues the top edge
          row(t, -1.0f, -1.0f, c[3], v[3]);
        }
      }
      for (int x = 0; x < size; ++x) {
        const size_t i = static_cast<size_t>(x);
        glm::vec3 colour = c[0][i];
        float value = v[0][i];
        if (tile) {
          const float a = bandWeight((static_cast<float>(x) + 0.5f) * inv);
          colour = (1.0f - a) * (1.0f - b) * c[0][i] + a * (1.0f - b) * c[1][i];
          value = (1.0f - a) * (1.0f - b) * v[0][i] + a * (1.0f - b) * v[1][i];
          if (b > 0.0f) {
            colour += (1.0f - a) * b * c[2][i] + a * b * c[3][i];
            value += (1.0f - a) * b * v[2][i] + a * b * v[3][i];
          }
        }
        uint8_t* p = &out.marble.pixels[(static_cast<size_t>(y) * n + i) * 4];
        p[0] = toByte(linearToSrgb(colour.x));
        p[1] = toByte(linearToSrgb(colour.y));
        p[2] = toByte(linearToSrgb(colour.z));
        uint8_t* g = &out.veins.pixels[(static_cast<size_t>(y) * n + i) * 4];
        g[0] = g[1] = g[2] = toByte(value);
      }
    }
  };
  const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work, i, threads);
  work(0, threads);
  for (auto& th : pool) th.join();
  return out;
}

}  // namespace marble
