#include "cmd_compare.h"

#include <cstdio>
#include <stdexcept>

#include "marble/core/error.h"
#include "marble/core/image_compare.h"
#include "scene_options.h"

namespace marble {

int runCompareCommand(const CompareOptions& o) {
  return reportErrors("compare", [&] {
    const CoveredImage ref = readExrWithCoverage(o.reference);
    const CoveredImage test = readExrWithCoverage(o.test);
    ImageComparison c;
    try {
      c = compareImages(ref, test);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.test, "", std::string(e.what()) + " (the reference " + o.reference + " sets the size)");
    }
    const char* refSource = coverageSourceName(ref.source);
    const char* testSource = coverageSourceName(test.source);
    if (o.json) {
      std::printf("{\"iou\": %.6f, \"scale\": %.6f, \"relative_rmse\": %.6f, \"ssim\": %.6f, "
                  "\"ref_pixels\": %lld, \"test_pixels\": %lld, \"joint_pixels\": %lld, "
                  "\"ref_coverage\": \"%s\", \"test_coverage\": \"%s\"}\n",
                  c.iou, c.scale, c.relative_rmse, c.ssim, c.ref_pixels, c.test_pixels, c.joint_pixels, refSource,
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
                  "SSIM             %.4f  (tone-mapped luma, 11x11 Gaussian window)\n",
                  c.iou, c.ref_pixels, c.test_pixels, c.joint_pixels, c.scale, c.relative_rmse, c.ssim);
    }
    return 0;
  });
}

}  // namespace marble
