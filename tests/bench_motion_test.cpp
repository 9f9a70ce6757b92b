// `marble bench --motion pattern` moves what the material's own vein model reads, so that its
// frames measure a pattern that really changes (src/app/bench_motion.cpp).
#include <gtest/gtest.h>

#include "../src/app/bench_motion.h"

namespace marble {
namespace {

Scene withModel(VeinModel model) {
  Scene s;
  s.material.vein_model = model;
  return s;
}

TEST(BenchMotion, PatternMovesTheWarpOfTheNetworkAndBrecciaModels) {
  for (VeinModel model : {VeinModel::Network, VeinModel::Breccia}) {
    const Scene base = withModel(model);
    const Scene moved = sceneAtFrame(base, BenchMotion::Pattern, 1);
    EXPECT_NE(moved.material.vein_warp, base.material.vein_warp);
    EXPECT_EQ(moved.material.turb_power, base.material.turb_power);  // unread by these models
  }
}

TEST(BenchMotion, PatternMovesTheTurbulenceOfThePapersModel) {
  const Scene base = withModel(VeinModel::Paper);
  const Scene moved = sceneAtFrame(base, BenchMotion::Pattern, 1);
  EXPECT_NE(moved.material.turb_power, base.material.turb_power);
  EXPECT_EQ(moved.material.vein_warp, base.material.vein_warp);
}

}  // namespace
}  // namespace marble
