// Blender's Principled subsurface parameters -> marble's coefficients, against numbers computed
// independently (Python, double precision) from Cycles 3.4.1's formulas: bssrdf_setup_radius's
// F_dr and 12-step bisection of the dipole Rd, subsurface_random_walk_remap at g = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "marble/core/error.h"
#include "marble/scene/material_io.h"
#include "marble/scene/material_scattering.h"

namespace marble {
namespace {

void expectRelative(float got, double want, double rel, const char* what) {
  EXPECT_NEAR(got, want, std::abs(want) * rel) << what;
}

TEST(MaterialScattering, AlphaPrimeIsCyclesBisection) {
  // The bisection's answers are midpoints of its 12th step: exact in float.
  EXPECT_EQ(cyclesAlphaPrime(0.87f, 1.5f), 0.999267578125f);
  EXPECT_EQ(cyclesAlphaPrime(0.85f, 1.5f), 0.999267578125f);  // same cell: Cycles' resolution, kept
  EXPECT_EQ(cyclesAlphaPrime(0.8f, 1.5f), 0.998779296875f);
  EXPECT_EQ(cyclesAlphaPrime(0.5f, 1.3f), 0.972412109375f);
  EXPECT_EQ(cyclesAlphaPrime(0.2f, 1.3f), 0.804443359375f);
  EXPECT_EQ(cyclesAlphaPrime(5e-5f, 1.5f), 0.0f);        // below 1e-4
  EXPECT_EQ(cyclesAlphaPrime(0.995f, 1.5f), 0.999999f);  // from 0.995
  // It inverts Rd to within one bisection step.
  for (float albedo : {0.05f, 0.3f, 0.6f, 0.9f, 0.98f}) {
    const float a = cyclesAlphaPrime(albedo, 1.55f);
    const float step = 1.0f / 4096.0f;
    EXPECT_LE(dipoleReflectance(std::max(a - step, 0.0f), 1.55f), albedo) << albedo;
    EXPECT_GE(dipoleReflectance(std::min(a + step, 1.0f), 1.55f), albedo) << albedo;
  }
}

TEST(MaterialScattering, SingleScatteringAlbedoIsWrenningesFitAtZeroAnisotropy) {
  expectRelative(cyclesSingleScatteringAlbedo(0.87f), 0.997589319, 1e-6, "0.87");
  expectRelative(cyclesSingleScatteringAlbedo(0.5f), 0.913700743, 1e-6, "0.5");
  expectRelative(cyclesSingleScatteringAlbedo(0.2f), 0.613351304, 1e-6, "0.2");
  EXPECT_EQ(cyclesSingleScatteringAlbedo(0.99f), 0.999999f);  // Cycles' upper clamp
  EXPECT_EQ(cyclesSingleScatteringAlbedo(0.01f), 0.2f);       // and its min_alpha
}

TEST(MaterialScattering, CoefficientsFromTheIssuesExample) {
  // base_color 0.87, 0.85, 0.8; subsurface_radius_mm 17, 12, 8; ior 1.5.
  const ScatteringCoefficients c = coefficientsFromRadius({0.87f, 0.85f, 0.8f}, {17.0f, 12.0f, 8.0f}, 1.5f);
  // sigma_a = (1 - alpha) sigma_t with alpha near 1 in float (as in Cycles): 1e-4 relative.
  expectRelative(c.sigma_a_mm.x, 0.00302516865, 1e-4, "sigma_a r");
  expectRelative(c.sigma_a_mm.y, 0.00671019911, 1e-4, "sigma_a g");
  expectRelative(c.sigma_a_mm.z, 0.0170348777, 1e-4, "sigma_a b");
  expectRelative(c.sigma_s_mm.x, 1.25187679, 1e-5, "sigma_s r");
  expectRelative(c.sigma_s_mm.y, 1.77106758, 1e-5, "sigma_s g");
  expectRelative(c.sigma_s_mm.z, 2.04855624, 1e-5, "sigma_s b");
  // Negative control: the mapping the reference script used before (radius = 1 / sigma_tr, no
  // albedo inversion) is a different stone: 1 / sigma_tr of these coefficients is not 17 mm.
  const float sigmaTr = std::sqrt(3.0f * c.sigma_a_mm.x * (c.sigma_a_mm.x + c.sigma_s_mm.x));
  EXPECT_GT(std::abs(1.0f / sigmaTr - 17.0f), 3.0f);
}

TEST(MaterialScattering, CoefficientsAwayFromMarble) {
  const ScatteringCoefficients c = coefficientsFromRadius({0.5f, 0.2f, 0.99f}, {1.0f, 2.0f, 3.0f}, 1.3f);
  expectRelative(c.sigma_a_mm.x, 0.299976464, 1e-4, "sigma_a r");
  expectRelative(c.sigma_a_mm.y, 0.25240017, 1e-4, "sigma_a g");
  // alpha is clamped to 0.999999f, 1 - 1.01e-6 in float (as in Cycles), not 1 - 1e-6: 1.3 % here.
  expectRelative(c.sigma_a_mm.z, 1.23168057e-05, 2e-2, "sigma_a b");
  expectRelative(c.sigma_s_mm.x, 3.47600286 - 0.299976464, 1e-5, "sigma_s r");
  expectRelative(c.sigma_s_mm.y, 0.652789399 - 0.25240017, 1e-5, "sigma_s g");
  expectRelative(c.sigma_s_mm.z, 12.3167934, 1e-5, "sigma_s b");
}

TEST(MaterialScattering, TheRadiusFormIsSelectedByItsKeysAndResolved) {
  std::vector<std::string> warnings;
  Material m = loadPreset("measured-marble");
  EXPECT_EQ(m.scattering, ScatteringForm::Coefficients);
  applyMaterialJson(m, nlohmann::json::parse(R"({"base_color": [0.87, 0.85, 0.8], "subsurface_radius_mm": [17, 12, 8],
                                                 "ior": 1.5, "roughness": 0.15})"),
                    "scene.json", "material.", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(m.scattering, ScatteringForm::Radius);
  expectRelative(m.sigma_s_mm.x, 1.25187679, 1e-5, "derived at load");
  // The same stone as a built-in preset, and through --set.
  const Material preset = loadPreset("principled-white");
  EXPECT_EQ(preset.scattering, ScatteringForm::Radius);
  EXPECT_EQ(preset.sigma_a_mm, m.sigma_a_mm);
  Material viaSet = loadPreset("measured-marble");
  setMaterialKey(viaSet, "base_color", "0.87,0.85,0.8");
  setMaterialKey(viaSet, "ior", "1.5");
  setMaterialKey(viaSet, "subsurface_radius_mm", "17,12,8");
  EXPECT_EQ(viaSet.sigma_s_mm, m.sigma_s_mm);
  setMaterialKey(viaSet, "base_color", "0.5,0.2,0.99");  // the coefficients follow the albedo
  EXPECT_NE(viaSet.sigma_s_mm, m.sigma_s_mm);
  // sigma_s_mm alone returns to the coefficient form, keeping the absorption in effect.
  const glm::vec3 absorption = viaSet.sigma_a_mm;
  setMaterialKey(viaSet, "sigma_s_mm", "2,2,2");
  EXPECT_EQ(viaSet.scattering, ScatteringForm::Coefficients);
  EXPECT_EQ(viaSet.sigma_a_mm, absorption);
  EXPECT_EQ(viaSet.sigma_s_mm, glm::vec3(2.0f));
}

TEST(MaterialScattering, BothFormsAtOnceIsAnError) {
  std::vector<std::string> warnings;
  Material m;
  try {
    applyMaterialJson(m, nlohmann::json::parse(R"({"subsurface_radius_mm": [1, 1, 1], "sigma_a_mm": [0.1, 0.1, 0.1]})"),
                      "scene.json", "material.", warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene.json: material.subsurface_radius_mm: give either", 0), 0u) << e.what();
  }
  // An explicit form says which one is meant (what saved files carry).
  applyMaterialJson(m, nlohmann::json::parse(R"({"scattering": "radius", "subsurface_radius_mm": [1, 1, 1],
                                                 "sigma_a_mm": [0.1, 0.1, 0.1]})"),
                    "scene.json", "material.", warnings);
  EXPECT_EQ(m.scattering, ScatteringForm::Radius);
  EXPECT_NE(m.sigma_a_mm, glm::vec3(0.1f));  // derived, not the written value
}

}  // namespace
}  // namespace marble
