// Every material parameter against the render modes (issue 14), from the parameters'
// descriptions (src/marble/scene/material_params.cpp): in a mode its description lists, changing
// it changes the picture; in every other mode the picture stays identical (so the panel's greyed
// controls and `--set`'s warning are right); and in every mode the frame drawn from the caches
// after the change equals one drawn without them (the groups the passes compare are all that
// they read).
#include <gtest/gtest.h>

#include "gl_support.h"
#include "marble/scene/material_params.h"
#include "marble/scene/material_scattering.h"

using namespace marble;
using namespace marble::test;

namespace {

float far(float value, float lo, float hi) { return value < 0.5f * (lo + hi) ? hi : lo; }

// A value of `p` far from `m`'s, so the change shows in a small picture.
ParamValue changedValue(const ParamDesc& p, const Material& m) {
  const ParamValue v = p.get(m);
  switch (p.type) {
    case ParamType::UInt: return std::get<long long>(v) + 1;
    case ParamType::Int: return static_cast<long long>(p.slider.lo);
    case ParamType::Float: {
      float hi = p.slider.hi;
      if (p.atMost) hi = std::min(hi, static_cast<float>(std::get<long long>(findParam(p.atMost)->get(m))));
      return far(std::get<float>(v), p.slider.lo, hi);
    }
    case ParamType::Vec3: {
      const glm::vec3 c = std::get<glm::vec3>(v);
      return glm::vec3(far(c.x, p.slider.lo, p.slider.hi), far(c.y, p.slider.lo, p.slider.hi),
                       far(c.z, p.slider.lo, p.slider.hi));
    }
    case ParamType::Colour: return glm::vec3(1.0f) - std::get<glm::vec3>(v);
    case ParamType::Choice: {
      for (const auto& c : p.choices)
        if (c.value != std::get<long long>(v)) return static_cast<long long>(c.value);
      return v;
    }
    case ParamType::Text: return v;
  }
  return v;
}

}  // namespace

// The materials each parameter is tried on: the default, and ones where the parameters that
// the default leaves unused (ParamDesc::active) are used: the vein models, the radius form.
std::vector<Material> bases() {
  Material paper;
  paper.vein2_amount = 0.5f;  // so vein2_color shows
  // The `reflectance` mode shows Schlick's term alone, F0 = mix(0.04, albedo, metalness): at
  // metalness 0 the albedo (the pattern, its colours) has no part in it.
  paper.metalness = 0.5f;
  Material network = paper, breccia = paper, radius = paper;
  network.vein_model = VeinModel::Network;
  network.fragment_tint = 0.5f;
  breccia.vein_model = VeinModel::Breccia;
  radius.scattering = ScatteringForm::Radius;
  resolveScattering(radius);
  return {paper, network, breccia, radius};
}

TEST(ParamModes, AParameterChangesThePictureExactlyInTheModesThatReadItAndCachesFollow) {
  glContext();
  Renderer renderer;
  renderer.setMesh(builtinMesh("sphere"));
  // The pattern per pixel: baking the turbulence grid for each seed, resolution, size, basis and
  // mapping tried would cost most of the test (the grid's pictures: turbulence_grid tests).
  renderer.setTurbulenceGridEnabled(false);
  const std::vector<Material> materials = bases();
  int checked = 0, inactiveChecked = 0;
  for (RenderMode mode : {RenderMode::Paper, RenderMode::Marble, RenderMode::Phong, RenderMode::OrenNayar,
                          RenderMode::Subsurface, RenderMode::Reflectance, RenderMode::Albedo, RenderMode::Thickness,
                          RenderMode::Floor}) {
    std::vector<Scene> scenes;
    std::vector<ImageRGBA8> before;
    for (const Material& m : materials) {
      Scene base;
      base.mesh = "builtin:sphere";
      base.render.width = base.render.height = 32;
      base.render.mode = mode;
      base.material = m;
      // The light from the side, so the paper's subsurface term (thickness) and marble's
      // transmission reach the visible half.
      base.light.position = glm::vec3(3.0f, 0.5f, -1.5f);
      renderer.invalidate();
      before.push_back(renderImage(renderer, base));
      scenes.push_back(base);
    }
    for (const auto& p : materialParams()) {
      if (p.type == ParamType::Text) continue;
      // Every change goes through resolveScattering, as from files, --set and the panel.
      const auto changedScene = [&](const Scene& base) {
        Scene changed = base;
        p.set(changed.material, changedValue(p, base.material));
        resolveScattering(changed.material);
        return changed;
      };
      size_t b = 0;
      while (b < materials.size() && !paramActive(p, materials[b])) ++b;
      ASSERT_LT(b, materials.size()) << p.key << ": no material of bases() uses it";
      const Scene& base = scenes[b];
      const Scene changed = changedScene(base);
      const std::string what = std::string(p.key) + " in mode " + renderModeName(mode);
      if (modeReads(p, mode)) {
        renderImage(renderer, base);  // the caches hold the unchanged material
        const ImageRGBA8 cached = renderImage(renderer, changed);
        renderer.invalidate();
        const ImageRGBA8 fresh = renderImage(renderer, changed);
        EXPECT_EQ(meanAbsDiff(cached, fresh), 0.0) << what << ": a cached frame differs from a fresh one";
        EXPECT_GT(meanAbsDiff(fresh, before[b]), 0.0) << what << ": listed as read, but the picture did not change";
      } else {
        // A fresh frame equal to the unchanged one: whatever the caches re-run gives it too.
        renderer.invalidate();
        EXPECT_EQ(meanAbsDiff(renderImage(renderer, changed), before[b]), 0.0)
            << what << ": not listed as read, but the picture changed";
      }
      // Where a material leaves it unused, changing it there changes nothing.
      size_t unused = 0;
      while (unused < materials.size() && paramActive(p, materials[unused])) ++unused;
      if (unused < materials.size()) {
        renderer.invalidate();
        EXPECT_EQ(meanAbsDiff(renderImage(renderer, changedScene(scenes[unused])), before[unused]), 0.0)
            << what << ": not used by material " << unused << " (" << p.inactive << "), but the picture changed";
        ++inactiveChecked;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 9 * 44);
  EXPECT_GE(inactiveChecked, 9 * 22);
}
