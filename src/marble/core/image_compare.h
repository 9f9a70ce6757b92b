#pragma once
// Comparing a test render against a reference (issue 5, item 9): how well the silhouettes agree,
// the exposure scale that best maps the test onto the reference, the relative error left after
// that scale, and the structural similarity (SSIM) of what a viewer would see.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "marble/core/image.h"

namespace marble {

// Where a coverage mask came from.
enum class CoverageSource {
  Alpha,   // the file's alpha channel (> 0.5)
  Values,  // "not exactly 0 in all three channels": the fallback for files without coverage alpha
};
const char* coverageSourceName(CoverageSource s);  // "alpha" or "values"

// An image and where the object covers it (1) or the background shows (0).
struct CoveredImage {
  ImageRGBF image;
  std::vector<uint8_t> coverage;  // width * height, row 0 is the top row
  CoverageSource source = CoverageSource::Values;
};

struct ImageComparison {
  double iou = 0.0;            // |A ∩ B| / |A ∪ B| of the two coverage masks (1 when both are empty)
  double scale = 1.0;          // k minimising Σ (k·test − ref)² over A ∩ B, all three channels
  double relative_rmse = 0.0;  // sqrt(Σ (k·test − ref)² / Σ ref²) over A ∩ B
  double ssim = 1.0;           // mean SSIM of tone-mapped luma over A ∪ B
  // Σ test / Σ ref over A ∩ B, all channels: how much more light the test carries overall. Unlike
  // 1/k it is not ruled by the few brightest pixels (a glint, a firefly).
  double energy_ratio = 1.0;
  long long ref_pixels = 0, test_pixels = 0, joint_pixels = 0;
};

// Coverage from the values alone: a pixel is background when all three channels are exactly 0
// (marble's --hdr and a Cycles render with a transparent film both leave exact zeros there).
std::vector<uint8_t> coverageFromValues(const ImageRGBF& image);

// Coverage from the alpha channel, or nothing (nullopt) when the alpha says nothing about it:
// no alpha channel, or an alpha of 1 everywhere that the file does not mark as coverage (marble's
// --hdr before it wrote coverage; a file marble writes with coverage is marked, see writeExr).
std::optional<std::vector<uint8_t>> coverageFromAlpha(const ImageRGBF& image, bool markedCoverage);

// Reads an OpenEXR file with its coverage: from alpha when it carries coverage (a Cycles render
// with a transparent film, marble's --hdr), else from the values (coverageFromValues), which
// calls covered-but-unlit pixels background. Throws InputError naming the file.
CoveredImage readExrWithCoverage(const std::filesystem::path& path);

// The four figures. Sizes must match (throws std::invalid_argument otherwise).
ImageComparison compareImages(const CoveredImage& ref, const CoveredImage& test);

// The image box-filtered by a whole factor (core/image_downsample.h), its coverage the blocks
// more than half covered. Comparing at a downsample scores what survives at a smaller size: a
// path tracer's per-pixel noise averages out, so its own noise floor rises toward 1.
// Throws std::invalid_argument when the size is not a multiple of the factor.
CoveredImage downsampleCovered(const CoveredImage& image, int factor);

// Reference | test side by side, each through the display transform (the test at exposure k),
// background black: the picture docs/quality.md shows for each scene.
ImageRGBA8 sideBySide(const CoveredImage& ref, const CoveredImage& test, double k);

// The display transform of the `marble` mode (shaders/post.frag.glsl), on one linear colour:
// Khronos PBR Neutral, then the sRGB transfer function; components in [0, 1].
glm::vec3 toneMapForDisplay(glm::vec3 linear);

// Mean SSIM (Wang et al. 2004) of two single-channel images in [0, 1], with an 11x11 Gaussian
// window (σ = 1.5), averaged over the pixels where `where` is nonzero (all when it is empty).
double meanSsim(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                const std::vector<uint8_t>& where);

}  // namespace marble
