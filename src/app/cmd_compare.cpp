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
    if (o.json) {
      std::printf("{\"iou\": %.6f, \"scale\": %.6f, \"relative_rmse\": %.6f, \"ssim\": %.6f, "
                  "\"ref_pixels\": %lld, \"test_pixels\": %lld, \"joint_pixels\": %lld}\n",
                  c.iou, c.scale, c.relative_rmse, c.ssim, c.ref_pixels, c.test_pixels, c.joint_pixels);
    } else {
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
