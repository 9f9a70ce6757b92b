// The renderer follows the passes' declarations (render/pass_list.h, issue 14): a fresh frame
// runs exactly the passes the list says the frame has (what `marble bench`, the panel and
// `--timings` show), and after a change a cached pass re-runs exactly when an input it declares
// changed or a pass it reads re-ran -- with the cached frame equal to a fresh one.
#include <gtest/gtest.h>

#include "gl_support.h"

#include "marble/render/pass_cache.h"
#include "marble/render/post_pass.h"

using namespace marble;
using namespace marble::test;

namespace {

Scene sphereScene(RenderMode mode) {
  Scene s;
  s.mesh = "builtin:sphere";
  s.render.width = s.render.height = 48;
  s.render.mode = mode;
  return s;
}

FrameInputs frameOf(const Scene& s) {
  const float w = static_cast<float>(s.render.width), h = static_cast<float>(s.render.height);
  return {s, glm::mat4(1.0f), cameraMatrices(s.camera, w / h), lightMatrices(s.light), s.render.width, s.render.height,
          s.render.mode == RenderMode::Marble ? seenVeinAttenuation(s) : 0.0f};
}

// Which cached passes must re-run going from `before` to `after`, by the declarations alone.
PerPass<bool> expectedRuns(const Scene& before, const Scene& after) {
  const FrameInputs a = frameOf(before), b = frameOf(after);
  PerPass<bool> runs;
  // `marble`'s post pass makes the albedo where the albedo pass would.
  auto made = [](Pass p, const Scene& s) {
    return passInFrame(p, s) || (p == Pass::Albedo && s.render.mode == RenderMode::Marble);
  };
  for (const PassDecl& d : passList()) {  // in frame order: what a pass reads is decided before it
    if (!made(d.pass, after)) continue;
    bool changed = d.everyFrame || !made(d.pass, before);  // no output yet
    for (size_t i = kRendererStateInputs; i < kPassInputCount; ++i)
      if ((d.inputs & (1u << i)) != 0 && !sameInput(static_cast<PassInput>(i), a, b)) changed = true;
    if (!sameGroups(before.material, after.material, passGroups(d.pass, after.render.mode))) changed = true;
    for (const PassDecl& q : passList())
      if ((passReads(d.pass, after) & passBit(q.pass)) != 0 && runs[q.pass]) changed = true;
    runs[d.pass] = changed;
  }
  return runs;
}

}  // namespace

TEST(PassInputs, AFreshFrameRunsExactlyThePassesTheListGivesIt) {
  glContext();
  std::vector<Scene> scenes;
  for (RenderMode m : {RenderMode::Marble, RenderMode::Paper, RenderMode::Normal, RenderMode::Albedo, RenderMode::Floor})
    scenes.push_back(sphereScene(m));
  Scene full = sphereScene(RenderMode::Marble);
  full.render.subsurface_resolution = SubsurfaceResolution::Full;
  Scene noAa = sphereScene(RenderMode::Paper);
  noAa.render.antialias = Antialias::None;
  Scene stage = sphereScene(RenderMode::Marble);
  stage.render.ground = true;
  scenes.insert(scenes.end(), {full, noAa, stage});
  for (const Scene& s : scenes) {
    Renderer renderer;
    renderer.setMesh(builtinMesh("sphere"));
    renderImage(renderer, s);
    const PassTimes t = renderer.passTimes(true);
    for (const PassDecl& d : passList()) {
      // `marble`'s albedo is evaluated by its post pass (DiffuseSource::Pattern), not by the albedo pass.
      EXPECT_EQ(t.ran[d.pass], passInFrame(d.pass, s)) << renderModeName(s.render.mode) << ": " << d.name;
    }
    EXPECT_EQ(t.diffuseSource, s.render.mode == RenderMode::Marble ? static_cast<int>(DiffuseSource::Pattern) : -1);
  }
}

TEST(PassInputs, ACachedPassReRunsExactlyWhenADeclaredInputChanged) {
  glContext();
  struct Change {
    const char* what;
    void (*apply)(Scene&);
  };
  const Change changes[] = {
      {"nothing", [](Scene&) {}},
      {"camera", [](Scene& s) { s.camera.position.x += 0.3f; }},
      {"light", [](Scene& s) { s.light.position.y += 0.7f; }},
      {"light colour", [](Scene& s) { s.light.color = glm::vec3(1.0f, 0.8f, 0.6f); }},
      {"exposure", [](Scene& s) { s.render.exposure = 0.5f; }},
      {"background", [](Scene& s) { s.render.background = glm::vec3(0.3f); }},
      {"roughness", [](Scene& s) { s.material.roughness = 0.6f; }},
      {"sigma_s", [](Scene& s) { s.material.sigma_s_mm *= 0.5f; }},
      {"k_schlick", [](Scene& s) { s.material.k_schlick = 0.9f; }},
      {"vein colour", [](Scene& s) { s.material.vein_color = glm::vec3(0.1f, 0.3f, 0.6f); }},
      {"base colour", [](Scene& s) { s.material.base_color = glm::vec3(0.3f, 0.5f, 0.2f); }},
      {"light intensity", [](Scene& s) { s.light.intensity *= 0.5f; }},
      {"frame size", [](Scene& s) { s.render.width = 40; }},
      {"vein model", [](Scene& s) { s.material.vein_model = VeinModel::Network; }},
      {"size", [](Scene& s) { s.mm_per_unit = 40.0f; }},
      {"environment", [](Scene& s) { s.render.environment_intensity = 0.2f; }},
      {"subsurface resolution", [](Scene& s) { s.render.subsurface_resolution = SubsurfaceResolution::Full; }},
      {"mode", [](Scene& s) { s.render.mode = s.render.mode == RenderMode::Marble ? RenderMode::Paper : RenderMode::Marble; }},
  };
  int reRuns = 0, cached = 0;  // the test must see both
  // invalidate(): each case starts from nothing stored, as a new renderer (whose programs,
  // once compiled, are kept: that is most of a new renderer's cost).
  Renderer renderer, fresh;
  renderer.setMesh(builtinMesh("sphere"));
  fresh.setMesh(builtinMesh("sphere"));
  for (RenderMode mode : {RenderMode::Marble, RenderMode::Paper}) {
    for (const Change& c : changes) {
      renderer.invalidate();
      const Scene before = sphereScene(mode);
      Scene after = before;
      c.apply(after);
      renderImage(renderer, before);
      const ImageRGBA8 cachedImage = renderImage(renderer, after);
      const PassTimes t = renderer.passTimes(true);
      const PerPass<bool> expected = expectedRuns(before, after);
      const std::string where = renderModeName(mode) + ", " + c.what + ": ";
      for (const PassDecl& d : passList()) {
        if (d.everyFrame) continue;
        if (d.pass == Pass::Albedo && after.render.mode == RenderMode::Marble) {
          // `marble`'s post pass evaluates the pattern where the albedo pass would have run.
          EXPECT_EQ(t.diffuseSource == static_cast<int>(DiffuseSource::Pattern), expected[d.pass]) << where << d.name;
          continue;
        }
        EXPECT_EQ(t.ran[d.pass], expected[d.pass]) << where << d.name;
        (t.ran[d.pass] ? reRuns : cached) += passInFrame(d.pass, after) ? 1 : 0;
      }
      // A stale pass moves thousands of pixels; a cached `marble` frame reading stored values may
      // differ from a fresh one (which evaluates them in another program) by one level in a few
      // (PassFixture.ScatteringChangeReRunsLightingAndBlurButNotGeometry).
      fresh.invalidate();
      EXPECT_LT(meanAbsDiff(cachedImage, renderImage(fresh, after)), 0.01) << where << "the cached frame is a fresh one's";
    }
  }
  EXPECT_GT(reRuns, 10);
  EXPECT_GT(cached, 10);
}
