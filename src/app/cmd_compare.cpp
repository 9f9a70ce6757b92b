#include "cmd_compare.h"

#include <cstdio>
#include <stdexcept>

#include "marble/core/error.h"
#include "marble/core/image.h"
#include "marble/core/image_compare.h"
#include "scene_options.h"

namespace marble {

int runCompareCommand(const CompareOptions& o) {
  return reportErrors("compare", [&] {
    CoveredImage ref = readExrWithCoverage(o.reference);
    CoveredImage test = readExrWithCoverage(o.test);
    auto shrink = [&](CoveredImage& img, const std::string& path) {
      try {
        img = downsampleCovered(img, o.downsample);
      } catch (const std::invalid_argument& e) {
        throw InputError(path, "--downsample", e.what());
      }
    };
    shrink(ref, o.reference);
    shrink(test, o.test);
    ImageComparison c;
    try {
      c = compareImages(ref, test);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.test, "", std::string(e.what()) + " (the reference " + o.reference + " sets the size)");
    }
    if (!o.sideBySide.empty()) writePng(o.sideBySide, sideBySide(ref, test, c.scale));
    const char* refSource = coverageSourceName(ref.source);
    const char* testSource = coverageSourceName(test.source);
    if (o.json) {
      std::printf("{\"iou\": %.6f, \"scale\": %.6f, \"relative_rmse\": %.6f, \"ssim\": %.6f, \"energy_ratio\": %.6f, "
                  "\"ref_pixels\": %lld, \"test_pixels\": %lld, \"joint_pixels\": %lld, "
                  "\"ref_coverage\": \"%s\", \"test_coverage\": \"%s\"}\n",
                  c.iou, c.scale, c.relative_rmse, c.ssim, c.energy_ratio, c.ref_pixels, c.test_pixels, c.joint_pixels, refSource,
                  testSource);
    } else {
      // Which rule made each silhouette: alpha (coverage written by the renderer) or values (a
      // pixel is background when exactly 0, which also calls covered-but-unlit pixels background).
      if (ref.source == test.source && ref.source == CoverageSource::Alpha)
        std::printf("silhouettes      from alpha in both files\n");
      else
        std::printf("silhouettes      reference from %s, test from %s (\"values\": non-zero radiance, "
                    "used where a file has no coverage alpha)\n",
                    refSource, testSource);
      std::printf("silhouette IoU   %.4f  (reference %lld px, test %lld px, both %lld px)\n"
                  "exposure scale   %.4f  (k minimising |k*test - ref|^2 over both masks)\n"
                  "relative RMSE    %.4f  (after k)\n"
                  "SSIM             %.4f  (tone-mapped luma, 11x11 Gaussian window)\n"
                  "energy ratio     %.4f  (sum of test / sum of reference over both masks)\n",
                  c.iou, c.ref_pixels, c.test_pixels, c.joint_pixels, c.scale, c.relative_rmse, c.ssim, c.energy_ratio);
      if (o.downsample > 1) std::printf("compared at      downsample %d (%dx%d)\n", o.downsample, ref.image.width, ref.image.height);
    }
    return 0;
  });
}

}  // namespace marble
