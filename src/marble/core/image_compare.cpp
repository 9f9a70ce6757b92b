#include "marble/core/image_compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "marble/core/error.h"
#include "marble/core/image_downsample.h"

namespace marble {

std::vector<uint8_t> coverageFromValues(const ImageRGBF& image) {
  std::vector<uint8_t> mask(static_cast<size_t>(image.width) * image.height);
  for (size_t i = 0; i < mask.size(); ++i) {
    const float* p = &image.pixels[i * 3];
    mask[i] = (p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f) ? 1 : 0;
  }
  return mask;
}

const char* coverageSourceName(CoverageSource s) { return s == CoverageSource::Alpha ? "alpha" : "values"; }

std::optional<std::vector<uint8_t>> coverageFromAlpha(const ImageRGBF& image, bool markedCoverage) {
  if (image.alpha.empty()) return std::nullopt;
  std::vector<uint8_t> mask(image.alpha.size());
  bool belowOne = false;
  for (size_t i = 0; i < mask.size(); ++i) {
    mask[i] = image.alpha[i] > 0.5f ? 1 : 0;
    belowOne = belowOne || image.alpha[i] < 1.0f;
  }
  // An unmarked alpha of 1 everywhere is what writers put when they have no coverage.
  if (!belowOne && !markedCoverage) return std::nullopt;
  return mask;
}

CoveredImage readExrWithCoverage(const std::filesystem::path& path) {
  // Alpha is the only coverage that survives pixels lit by nothing (exactly 0 inside the object,
  // e.g. the dark side of a back-lit statue).
  bool marked = false;
  CoveredImage out;
  out.image = readExr(path, &marked);
  for (float v : out.image.pixels)
    if (!std::isfinite(v)) throw InputError(path.string(), "", "cannot read EXR: a pixel is NaN or infinite");
  if (auto mask = coverageFromAlpha(out.image, marked)) {
    out.coverage = std::move(*mask);
    out.source = CoverageSource::Alpha;
  } else {
    out.coverage = coverageFromValues(out.image);
    out.source = CoverageSource::Values;
  }
  return out;
}

glm::vec3 toneMapForDisplay(glm::vec3 color) {
  // Khronos PBR Neutral (Khronos 3D Commerce, 2024), as in shaders/post.frag.glsl.
  const float start = 0.8f - 0.04f;
  const float desaturation = 0.15f;
  const float x = std::min({color.r, color.g, color.b});
  const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  color -= offset;
  const float peak = std::max({color.r, color.g, color.b});
  if (peak >= start) {
    const float d = 1.0f - start;
    const float newPeak = 1.0f - d * d / (peak + d - start);
    color *= newPeak / peak;
    const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    color = glm::mix(color, glm::vec3(newPeak), g);
  }
  // sRGB OETF (IEC 61966-2-1).
  glm::vec3 out;
  for (int c = 0; c < 3; ++c) {
    const float v = std::clamp(color[c], 0.0f, 1.0f);
    out[c] = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

namespace {

// Separable Gaussian blur, 11 taps, σ = 1.5 (Wang et al. 2004, §III-C). At the border the
// window is cut and its weights renormalised, so no value from outside the image is invented.
std::vector<double> gaussianBlur(const std::vector<double>& in, int w, int h) {
  std::array<double, 11> k{};
  for (int i = 0; i < 11; ++i) k[i] = std::exp(-(i - 5) * (i - 5) / (2.0 * 1.5 * 1.5));
  auto pass = [&](const std::vector<double>& src, bool horizontal) {
    std::vector<double> dst(src.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double sum = 0.0, wsum = 0.0;
        for (int i = -5; i <= 5; ++i) {
          const int xx = horizontal ? x + i : x, yy = horizontal ? y : y + i;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          sum += k[i + 5] * src[static_cast<size_t>(yy) * w + xx];
          wsum += k[i + 5];
        }
        dst[static_cast<size_t>(y) * w + x] = sum / wsum;
      }
    return dst;
  };
  return pass(pass(in, true), false);
}

}  // namespace

double meanSsim(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                const std::vector<uint8_t>& where) {
  const size_t n = static_cast<size_t>(width) * height;
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (size_t i = 0; i < n; ++i) {
    x[i] = a[i];
    y[i] = b[i];
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const auto mx = gaussianBlur(x, width, height), my = gaussianBlur(y, width, height);
  const auto mxx = gaussianBlur(xx, width, height), myy = gaussianBlur(yy, width, height);
  const auto mxy = gaussianBlur(xy, width, height);
  // Wang et al. 2004, eq. 13, dynamic range L = 1: C1 = (0.01 L)², C2 = (0.03 L)².
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double sum = 0.0;
  long long count = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!where.empty() && !where[i]) continue;
    const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i], cov = mxy[i] - mx[i] * my[i];
    sum += ((2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2)) /
           ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 1.0;
}

ImageComparison compareImages(const CoveredImage& ref, const CoveredImage& test) {
  const int w = ref.image.width, h = ref.image.height;
  if (w != test.image.width || h != test.image.height)
    throw std::invalid_argument("sizes differ: " + std::to_string(w) + "x" + std::to_string(h) + " and " +
                                std::to_string(test.image.width) + "x" + std::to_string(test.image.height));
  const size_t n = static_cast<size_t>(w) * h;
  ImageComparison r;
  long long unionCount = 0;
  double tr = 0.0, tt = 0.0, rr = 0.0, tSum = 0.0, rSum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const bool a = ref.coverage[i] != 0, b = test.coverage[i] != 0;
    r.ref_pixels += a;
    r.test_pixels += b;
    unionCount += (a || b);
    if (!(a && b)) continue;
    ++r.joint_pixels;
    for (int c = 0; c < 3; ++c) {
      const double rv = ref.image.pixels[i * 3 + c], tv = test.image.pixels[i * 3 + c];
      tr += tv * rv;
      tt += tv * tv;
      rr += rv * rv;
      tSum += tv;
      rSum += rv;
    }
  }
  r.iou = unionCount > 0 ? static_cast<double>(r.joint_pixels) / static_cast<double>(unionCount) : 1.0;
  // Least squares: d/dk Σ (k t − r)² = 0 gives k = Σ t r / Σ t².
  r.scale = tt > 0.0 ? tr / tt : 1.0;
  r.energy_ratio = rSum > 0.0 ? tSum / rSum : 1.0;
  // Σ (k t − r)² = k² Σt² − 2k Σtr + Σr², expanded so one pass suffices.
  const double residual = std::max(0.0, r.scale * r.scale * tt - 2.0 * r.scale * tr + rr);
  r.relative_rmse = rr > 0.0 ? std::sqrt(residual / rr) : (residual > 0.0 ? 1.0 : 0.0);

  // SSIM on what a viewer sees: both images through the `marble` mode's display transform, the
  // test at the best-fit exposure (the exposure mismatch is reported by `scale` already), then
  // Rec. 709 luma Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' of the encoded values. Averaged over the
  // union of the masks: the shared black background would only inflate the figure.
  std::vector<float> ya(n), yb(n);
  std::vector<uint8_t> where(n);
  const glm::vec3 luma(0.2126f, 0.7152f, 0.0722f);
  const float k = static_cast<float>(r.scale);
  for (size_t i = 0; i < n; ++i) {
    const float* p = &ref.image.pixels[i * 3];
    const float* q = &test.image.pixels[i * 3];
    ya[i] = glm::dot(luma, toneMapForDisplay(glm::vec3(p[0], p[1], p[2])));
    yb[i] = glm::dot(luma, toneMapForDisplay(k * glm::vec3(q[0], q[1], q[2])));
    where[i] = (ref.coverage[i] || test.coverage[i]) ? 1 : 0;
  }
  r.ssim = unionCount > 0 ? meanSsim(ya, yb, w, h, where) : 1.0;
  return r;
}

CoveredImage downsampleCovered(const CoveredImage& image, int factor) {
  if (factor == 1) return image;
  CoveredImage out;
  out.image = downsampleLinear(image.image, factor);
  out.source = image.source;
  ImageRGBF mask{image.image.width, image.image.height, {}};
  mask.pixels.reserve(image.coverage.size() * 3);
  for (uint8_t c : image.coverage) mask.pixels.insert(mask.pixels.end(), 3, c ? 1.0f : 0.0f);
  const ImageRGBF blocks = downsampleLinear(mask, factor);
  out.coverage.resize(static_cast<size_t>(blocks.width) * blocks.height);
  for (size_t i = 0; i < out.coverage.size(); ++i) out.coverage[i] = blocks.pixels[i * 3] > 0.5f ? 1 : 0;
  return out;
}

ImageRGBA8 sideBySide(const CoveredImage& ref, const CoveredImage& test, double k) {
  const int w = ref.image.width, h = ref.image.height;
  ImageRGBA8 out{2 * w, h, std::vector<uint8_t>(static_cast<size_t>(2 * w) * h * 4, 0)};
  auto paint = [&](const CoveredImage& img, int x0, float scale) {
    for (int y = 0; y < std::min(h, img.image.height); ++y)
      for (int x = 0; x < std::min(w, img.image.width); ++x) {
        const size_t i = static_cast<size_t>(y) * img.image.width + x;
        uint8_t* p = &out.pixels[(static_cast<size_t>(y) * 2 * w + x0 + x) * 4];
        p[3] = 255;
        if (!img.coverage[i]) continue;
        const float* c = &img.image.pixels[i * 3];
        const glm::vec3 e = toneMapForDisplay(scale * glm::vec3(c[0], c[1], c[2]));
        for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>(std::lround(e[ch] * 255.0f));
      }
  };
  paint(ref, 0, 1.0f);
  paint(test, w, static_cast<float>(k));
  return out;
}

}  // namespace marble
