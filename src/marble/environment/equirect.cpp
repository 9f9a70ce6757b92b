#include "marble/environment/equirect.h"

#include <algorithm>
#include <cmath>

namespace marble {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

glm::vec3 equirectDirection(double u, double v) {
  const double phi = (u - 0.5) * 2.0 * kPi, theta = v * kPi;
  const double s = std::sin(theta);
  return glm::vec3(static_cast<float>(s * std::sin(phi)), static_cast<float>(std::cos(theta)),
                   static_cast<float>(-s * std::cos(phi)));
}

glm::vec2 equirectUv(const glm::vec3& d) {
  const float u = 0.5f + std::atan2(d.x, -d.z) * static_cast<float>(0.5 / kPi);
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) * static_cast<float>(1.0 / kPi);
  return {u, v};
}

double equirectTexelSolidAngle(int y, int width, int height) {
  const double t0 = kPi * y / height, t1 = kPi * (y + 1) / height;
  return 2.0 * kPi / width * (std::cos(t0) - std::cos(t1));
}

glm::vec3 sampleEquirect(const ImageRGBF& img, float u, float v) {
  const float x = u * static_cast<float>(img.width) - 0.5f;
  const float y = std::clamp(v * static_cast<float>(img.height) - 0.5f, 0.0f, static_cast<float>(img.height - 1));
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  // Wrap horizontally (the seam at u = 0 and 1 is the same meridian).
  int x0 = static_cast<int>(fx) % img.width;
  if (x0 < 0) x0 += img.width;
  const int x1 = x0 + 1 == img.width ? 0 : x0 + 1;
  const int y0 = static_cast<int>(fy), y1 = std::min(y0 + 1, img.height - 1);
  const glm::vec3 top = glm::mix(texelAt(img, x0, y0), texelAt(img, x1, y0), tx);
  const glm::vec3 bottom = glm::mix(texelAt(img, x0, y1), texelAt(img, x1, y1), tx);
  return glm::mix(top, bottom, ty);
}

ImageRGBF resampleEquirect(const ImageRGBF& src, int width, int height) {
  // Separable: columns first (uniform weights), then rows weighted by their solid angle.
  const double sx = static_cast<double>(src.width) / width, sy = static_cast<double>(src.height) / height;
  ImageRGBF wide{width, src.height, std::vector<float>(static_cast<size_t>(width) * src.height * 3)};
  for (int y = 0; y < src.height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double a = x * sx, b = (x + 1) * sx;
      glm::dvec3 sum(0.0);
      double wsum = 0.0;
      for (int i = static_cast<int>(a); i < src.width && i < b; ++i) {
        const double w = std::min<double>(i + 1, b) - std::max<double>(i, a);
        sum += w * glm::dvec3(texelAt(src, i, y));
        wsum += w;
      }
      float* out = &wide.pixels[(static_cast<size_t>(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(sum[c] / wsum);
    }
  }
  ImageRGBF out{width, height, std::vector<float>(static_cast<size_t>(width) * height * 3)};
  for (int y = 0; y < height; ++y) {
    const double a = y * sy, b = (y + 1) * sy;
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      double wsum = 0.0;
      for (int j = static_cast<int>(a); j < src.height && j < b; ++j) {
        const double w = (std::min<double>(j + 1, b) - std::max<double>(j, a)) * equirectTexelSolidAngle(j, 1, src.height);
        sum += w * glm::dvec3(texelAt(wide, x, j));
        wsum += w;
      }
      float* p = &out.pixels[(static_cast<size_t>(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(wsum > 0.0 ? sum[c] / wsum : 0.0);
    }
  }
  return out;
}

std::vector<ImageRGBF> equirectMipChain(const ImageRGBF& base) {
  std::vector<ImageRGBF> chain{base};
  while (chain.back().width > 1 || chain.back().height > 1) {
    const ImageRGBF& s = chain.back();
    const int w = std::max(1, s.width / 2), h = std::max(1, s.height / 2);
    ImageRGBF m{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int x0 = std::min(2 * x, s.width - 1), x1 = std::min(2 * x + 1, s.width - 1);
        const int y0 = std::min(2 * y, s.height - 1), y1 = std::min(2 * y + 1, s.height - 1);
        // Rows weighted by their solid angle, so every level has the same integral as the base.
        const float w0 = static_cast<float>(equirectTexelSolidAngle(y0, 1, s.height));
        const float w1 = y1 == y0 ? 0.0f : static_cast<float>(equirectTexelSolidAngle(y1, 1, s.height));
        const glm::vec3 avg = (w0 * (texelAt(s, x0, y0) + texelAt(s, x1, y0)) + w1 * (texelAt(s, x0, y1) + texelAt(s, x1, y1))) /
                              (2.0f * (w0 + w1));
        float* p = &m.pixels[(static_cast<size_t>(y) * w + x) * 3];
        p[0] = avg.r;
        p[1] = avg.g;
        p[2] = avg.b;
      }
    chain.push_back(std::move(m));
  }
  return chain;
}

glm::dvec3 equirectMean(const ImageRGBF& img) {
  glm::dvec3 sum(0.0);
  for (int y = 0; y < img.height; ++y) {
    glm::dvec3 row(0.0);
    for (int x = 0; x < img.width; ++x) row += glm::dvec3(texelAt(img, x, y));
    sum += row * equirectTexelSolidAngle(y, img.width, img.height);
  }
  return sum / (4.0 * kPi);
}

}  // namespace marble
