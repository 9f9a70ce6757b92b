// How the `marble` frame is split over passes (issue 8): which pass re-runs for which change,
// the screen passes' rectangle, the half-resolution subsurface blur, and the specialized
// programs. Checked on pictures and on Renderer::passTimes' "ran" flags.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gl_support.h"
#include <glm/gtc/matrix_transform.hpp>

#include "marble/gl/program_variants.h"
#include "marble/render/screen_rect.h"

using namespace marble;
using namespace marble::test;

namespace {

Scene marbleScene(const std::string& mesh, int size) {
  Scene s;
  s.mesh = "builtin:" + mesh;
  s.render.width = s.render.height = size;
  s.render.mode = RenderMode::Marble;
  return s;
}

struct PassFixture : ::testing::Test {
  HeadlessContext& context = glContext();
  Renderer renderer;
};

// The same scene drawn by a renderer with no caches: what a cached frame must equal.
ImageRGBA8 freshRender(const std::string& mesh, const Scene& s) {
  Renderer fresh;
  fresh.setMesh(builtinMesh(mesh));
  return renderImage(fresh, s);
}

}  // namespace

TEST_F(PassFixture, GlossChangeReRunsOnlyThePostPassAndStillChangesThePicture) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  const ImageRGBA8 before = renderImage(renderer, s);
  s.material.roughness = 0.6f;
  const ImageRGBA8 after = renderImage(renderer, s);
  const PassTimes t = renderer.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::LightDepth]);
  EXPECT_FALSE(t.ran[Pass::Geometry]);
  EXPECT_FALSE(t.ran[Pass::Lighting]);
  EXPECT_EQ(t.diffuseSource, static_cast<int>(DiffuseSource::Stored)) << "the diffuse part is reused";
  EXPECT_GT(meanAbsDiff(before, after), 0.2) << "the highlight must change";
  EXPECT_EQ(meanAbsDiff(after, freshRender("sphere", s)), 0.0);
}

// The lighting and post passes compile the light's kind into their programs (LIGHT_DIRECTIONAL,
// shaders/light_geometry.glsl): a renderer whose light turns from a point light to a directional
// one and back must draw what fresh renderers draw, so each frame used the program of its own kind.
TEST_F(PassFixture, LightKindChangeUsesTheProgramOfThatKindAndMatchesAFreshRender) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  const ImageRGBA8 point = renderImage(renderer, s);
  EXPECT_EQ(meanAbsDiff(point, freshRender("sphere", s)), 0.0);
  s.light.type = LightType::Directional;
  const ImageRGBA8 directional = renderImage(renderer, s);
  EXPECT_GT(meanAbsDiff(point, directional), 0.2) << "another light: another picture";
  EXPECT_EQ(meanAbsDiff(directional, freshRender("sphere", s)), 0.0);
  s.light.type = LightType::Point;
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, s), point), 0.0);
}

// isCurrent: whether a target holding a frame still holds what render() would draw (the viewer
// and the benchmark skip such frames). Any change of the scene, model or size, of what the
// renderer holds (mesh, environment), or a later frame drawn elsewhere makes it false; a target
// with no token (new, or drawn into by other means) is never current.
TEST_F(PassFixture, IsCurrentTellsWhenAFrameWouldDrawTheSame) {
  renderer.setMesh(builtinMesh("sphere"));
  const Scene s = marbleScene("sphere", 64);
  const glm::mat4 one(1.0f);
  OffscreenTarget target(64, 64), other(64, 64);
  const Renderer::FrameToken none;
  EXPECT_FALSE(renderer.isCurrent(s, one, none, 64, 64)) << "nothing drawn yet";
  const Renderer::FrameToken first = renderer.render(s, one, target.fbo(), 64, 64);
  Renderer::FrameToken shown = first;
  EXPECT_TRUE(renderer.isCurrent(s, one, shown, 64, 64));
  EXPECT_FALSE(renderer.isCurrent(s, one, none, 64, 64)) << "a target with no frame";
  EXPECT_FALSE(renderer.isCurrent(s, one, shown, 64, 63)) << "another size";
  EXPECT_FALSE(renderer.isCurrent(s, glm::scale(one, glm::vec3(1.01f)), shown, 64, 64)) << "the model moved";
  Scene brighter = s;
  brighter.render.exposure = 1.0f;
  EXPECT_FALSE(renderer.isCurrent(brighter, one, shown, 64, 64)) << "any field of the scene";
  const Renderer::FrameToken elsewhere = renderer.render(s, one, other.fbo(), 64, 64);
  EXPECT_FALSE(renderer.isCurrent(s, one, shown, 64, 64)) << "a later frame went to another target";
  EXPECT_TRUE(renderer.isCurrent(s, one, elsewhere, 64, 64));
  // Tokens are never handed out twice, across renderers too: another renderer's first frame
  // (a counter per renderer would give it the same serial as `first`) is not `first`.
  Renderer second;
  second.setMesh(builtinMesh("sphere"));
  EXPECT_TRUE(second.isCurrent(s, one, second.render(s, one, other.fbo(), 64, 64), 64, 64));
  EXPECT_FALSE(second.isCurrent(s, one, first, 64, 64)) << "another renderer's frame";
  shown = renderer.render(s, one, target.fbo(), 64, 64);
  renderer.setMesh(builtinMesh("torus"));
  EXPECT_FALSE(renderer.isCurrent(s, one, shown, 64, 64)) << "a new mesh";
  shown = renderer.render(s, one, target.fbo(), 64, 64);
  renderer.clearEnvironmentMap();
  EXPECT_FALSE(renderer.isCurrent(s, one, shown, 64, 64)) << "the environment";
}

TEST_F(PassFixture, ScatteringChangeReRunsLightingAndBlurButNotGeometry) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  renderImage(renderer, s);
  s.material.sigma_s_mm *= 0.1f;
  const ImageRGBA8 cached = renderImage(renderer, s);
  const PassTimes t = renderer.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::Geometry]);
  EXPECT_TRUE(t.ran[Pass::Lighting]);
  EXPECT_EQ(t.diffuseSource, static_cast<int>(DiffuseSource::StoredAlbedo)) << "the albedo is reused";
  // Different programs (the fresh frame evaluates the pattern): the stored values are used as
  // stored on both sides, but the two compilations may round a value differently -- one level
  // in one pixel was seen; a real difference would move thousands.
  EXPECT_LT(meanAbsDiff(cached, freshRender("sphere", s)), 0.01);
}

TEST_F(PassFixture, PatternChangeReRunsOnlyThePatternAndMatchesAFreshRender) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  renderImage(renderer, s);
  s.material.seed += 17;  // another block of the same stone: the pattern group only
  const ImageRGBA8 cached = renderImage(renderer, s);
  const PassTimes t = renderer.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::Geometry]);
  EXPECT_FALSE(t.ran[Pass::Albedo]) << "`marble` evaluates the pattern in its post pass";
  EXPECT_EQ(t.diffuseSource, static_cast<int>(DiffuseSource::Pattern));
  EXPECT_FALSE(t.ran[Pass::Lighting]) << "the light entering the stone does not depend on the pattern";
  EXPECT_EQ(meanAbsDiff(cached, freshRender("sphere", s)), 0.0);
}

// Frames that change only the pattern (`--motion pattern`, the panel's pattern sliders) take the
// reflected and the upsampled blurred light from the frame before (SurfaceReuse): the first such
// frame stores them, the next ones read them back. Each equals a fresh render bit for bit, for
// the paper's model and the two vein models; a change of anything else (the gloss, the camera)
// computes them again. Negative controls (docs/performance.md, fifteenth session): reading the
// stored light in place of the stored reflected light, or keys that ignore the gloss, fail here.
TEST_F(PassFixture, PatternOnlyFramesReuseTheSurfaceAndMatchAFreshRender) {
  for (VeinModel model : {VeinModel::Paper, VeinModel::Network, VeinModel::Breccia}) {
    Renderer r;
    r.setMesh(builtinMesh("sphere"));
    Scene s = marbleScene("sphere", 64);
    s.material.vein_model = model;
    const std::string where = "vein model " + std::to_string(static_cast<int>(model)) + ": ";
    renderImage(r, s);
    EXPECT_EQ(r.passTimes(true).surfaceReuse, static_cast<int>(SurfaceReuse::None)) << where << "the first frame";
    const int expected[] = {static_cast<int>(SurfaceReuse::Store), static_cast<int>(SurfaceReuse::Read),
                            static_cast<int>(SurfaceReuse::Read)};
    for (int frame = 0; frame < 3; ++frame) {
      s.material.seed += 17;  // the pattern group only
      s.material.vein_warp *= 1.2f;
      const ImageRGBA8 cached = renderImage(r, s);
      EXPECT_EQ(r.passTimes(true).surfaceReuse, expected[frame]) << where << "pattern frame " << frame;
      EXPECT_FALSE(r.passTimes(true).ran[Pass::Lighting]) << where;
      EXPECT_EQ(meanAbsDiff(cached, freshRender("sphere", s)), 0.0) << where << "pattern frame " << frame;
    }
    // The gloss with the pattern: the reflected light changed, nothing is read back.
    s.material.roughness = 0.6f;
    s.material.seed += 17;
    EXPECT_EQ(meanAbsDiff(renderImage(r, s), freshRender("sphere", s)), 0.0) << where << "gloss and pattern";
    EXPECT_EQ(r.passTimes(true).surfaceReuse, static_cast<int>(SurfaceReuse::None)) << where << "gloss";
    // The camera: everything is new; the next pattern frame stores again, the one after reads.
    s.camera.position += glm::vec3(0.3f, 0.1f, 0.0f);
    EXPECT_EQ(meanAbsDiff(renderImage(r, s), freshRender("sphere", s)), 0.0) << where << "camera";
    EXPECT_EQ(r.passTimes(true).surfaceReuse, static_cast<int>(SurfaceReuse::None)) << where << "camera";
    for (int frame = 0; frame < 2; ++frame) {
      s.material.seed += 17;
      EXPECT_EQ(meanAbsDiff(renderImage(r, s), freshRender("sphere", s)), 0.0) << where << "after the camera";
      EXPECT_EQ(r.passTimes(true).surfaceReuse, expected[frame]) << where << "after the camera " << frame;
    }
  }
}

// The base colour is another matter since the bounce (shaders/bounce.glsl): the light bounced
// inside the object comes off the stone with its base colour, which the bounce pass's last draw
// applies to its gathers (bounce_merge.frag.glsl); so a base colour re-runs the bounce pass (that
// draw alone: BouncePass::run's `gather`) and the lighting, and the frame still equals a fresh one.
TEST_F(PassFixture, BaseColourChangeReRunsTheBounceAndTheLightingAndMatchesAFreshRender) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  renderImage(renderer, s);
  s.material.base_color = glm::vec3(0.3f, 0.5f, 0.2f);
  const ImageRGBA8 cached = renderImage(renderer, s);
  const PassTimes t = renderer.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::Geometry]);
  EXPECT_FALSE(t.ran[Pass::LightDepth]);
  EXPECT_TRUE(t.ran[Pass::Bounce]) << "its last draw applies the emitters' base colour";
  EXPECT_TRUE(t.ran[Pass::Lighting]) << "it reads the bounce";
  EXPECT_EQ(meanAbsDiff(cached, freshRender("sphere", s)), 0.0);
}

// The rest of the ramp (vein colours, sharpness) is the pattern's alone: in `marble` it re-runs
// neither the lighting nor the blur (it did while the lighting read the whole colour group for
// the bounce's base colour), and the frame still equals a fresh one.
TEST_F(PassFixture, VeinColourChangeReRunsNeitherTheLightingNorTheBlur) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 64);
  renderImage(renderer, s);
  s.material.vein_color = glm::vec3(0.1f, 0.3f, 0.6f);
  s.material.vein2_color = glm::vec3(0.2f, 0.2f, 0.5f);
  const ImageRGBA8 cached = renderImage(renderer, s);
  const PassTimes t = renderer.passTimes(true);
  EXPECT_FALSE(t.ran[Pass::Lighting]);
  EXPECT_FALSE(t.ran[Pass::SubsurfaceBlur]);
  EXPECT_FALSE(t.ran[Pass::Bounce]);
  EXPECT_EQ(t.diffuseSource, static_cast<int>(DiffuseSource::Pattern)) << "the pattern is evaluated anew";
  EXPECT_EQ(meanAbsDiff(cached, freshRender("sphere", s)), 0.0);
}

// The albedo texture is written by the albedo pass (other modes) or by marble's post pass; each
// mode reuses only what its own pass wrote (two programs need not round the pattern alike: with
// the paper's vein colours a few pixels came out one 8-bit level apart), so a mode switch
// re-evaluates the pattern once and every frame equals a fresh one.
TEST_F(PassFixture, ModesReuseOnlyTheAlbedoTheirOwnPassWrote) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene marble = marbleScene("sphere", 64);
  Scene paper = marble;
  paper.render.mode = RenderMode::Paper;
  renderImage(renderer, marble);
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, paper), freshRender("sphere", paper)), 0.0) << "after marble";
  EXPECT_TRUE(renderer.passTimes(true).ran[Pass::Albedo]) << "marble's post pass wrote the albedo";
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, marble), freshRender("sphere", marble)), 0.0) << "after paper";
  EXPECT_EQ(renderer.passTimes(true).diffuseSource, static_cast<int>(DiffuseSource::Pattern));
  paper.light.position = marble.light.position = glm::vec3(-2.0f, 3.0f, 2.0f);
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, marble), freshRender("sphere", marble)), 0.0) << "light moved";
  EXPECT_EQ(renderer.passTimes(true).diffuseSource, static_cast<int>(DiffuseSource::StoredAlbedo))
      << "marble reuses its own albedo";
  paper.material.vein_color = glm::vec3(0.1f, 0.3f, 0.6f);
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, paper), freshRender("sphere", paper)), 0.0);
  EXPECT_TRUE(renderer.passTimes(true).ran[Pass::Albedo]) << "the paper's mode runs the albedo pass";
}

// The blur's depth buffer is made from the G-buffer's depth; a frame of another mode moving
// the camera re-runs the geometry pass but not the blur's depth (the other modes have no blur),
// so the next `marble` frame must see that the G-buffer changed since the blur's depth was made
// (pass_list.h: BlurDepth reads Geometry), not merely whether the geometry ran in this frame.
TEST_F(PassFixture, BlurDepthFollowsAGeometryChangeMadeInAnotherMode) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene marble = marbleScene("sphere", 64);
  renderImage(renderer, marble);
  Scene paper = marble;
  paper.render.mode = RenderMode::Paper;
  paper.camera.position = marble.camera.position = glm::vec3(1.5f, 0.4f, 2.2f);
  renderImage(renderer, paper);
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, marble), freshRender("sphere", marble)), 0.0);
}

// Views of buffers show no pattern: they do not evaluate it, and a shading mode after them
// still gets the right albedo.
TEST_F(PassFixture, BufferViewsDoNotEvaluateThePattern) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 48);
  for (RenderMode mode : {RenderMode::Normal, RenderMode::Depth, RenderMode::Position, RenderMode::Thickness,
                          RenderMode::LightDepth}) {
    s.render.mode = mode;
    renderImage(renderer, s);
    EXPECT_FALSE(renderer.passTimes(true).ran[Pass::Albedo]) << renderModeName(mode);
  }
  s.render.mode = RenderMode::Paper;
  const ImageRGBA8 paper = renderImage(renderer, s);
  EXPECT_TRUE(renderer.passTimes(true).ran[Pass::Albedo]);
  EXPECT_EQ(meanAbsDiff(paper, freshRender("sphere", s)), 0.0);
  s.render.mode = RenderMode::Marble;
  EXPECT_EQ(meanAbsDiff(renderImage(renderer, s), freshRender("sphere", s)), 0.0);
}

TEST_F(PassFixture, ScreenRectangleHoldsEveryPixelOfTheObject) {
  // In the `normal` view every covered pixel differs from the background; all of them must lie
  // inside the rectangle the screen passes are scissored to (else the object would be cut).
  for (const char* mesh : {"sculpture", "torus", "slab"}) {
    const Mesh m = builtinMesh(mesh);
    renderer.setMesh(m);
    Scene s = marbleScene(mesh, 120);
    s.render.mode = RenderMode::Normal;
    s.camera.position = glm::vec3(1.2f, 0.8f, 2.6f);  // close: the object fills much of the frame
    const ImageRGBA8 img = renderImage(renderer, s);
    glm::vec3 lo = m.positions.front(), hi = lo;
    for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const CameraMatrices cam = cameraMatrices(s.camera, 1.0f);
    const ScreenRect r = projectedBounds(lo, hi, cam.viewProj, 120, 120);
    int covered = 0;
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 120; ++x) {
        if (glm::length(pixel(img, x, y) - s.render.background) < 0.02f) continue;
        ++covered;
        const int glY = 119 - y;  // the image is top row first, GL's rectangle bottom-up
        EXPECT_TRUE(x >= r.x && x < r.x + r.width && glY >= r.y && glY < r.y + r.height) << mesh << " " << x << "," << y;
      }
    EXPECT_GT(covered, 500) << mesh;
  }
}

TEST_F(PassFixture, HalfResolutionBlurIsCloseToFullResolution) {
  renderer.setMesh(builtinMesh("sculpture"));
  Scene s = marbleScene("sculpture", 128);
  s.render.subsurface_resolution = SubsurfaceResolution::Full;
  const ImageRGBA8 full = renderImage(renderer, s);
  s.render.subsurface_resolution = SubsurfaceResolution::Half;
  const ImageRGBA8 half = renderImage(renderer, s);
  EXPECT_TRUE(renderer.passTimes(true).ran[Pass::Lighting]) << "the resolution is an input of the blur";
  const double diff = meanAbsDiff(full, half);
  EXPECT_GT(diff, 0.0) << "they are different computations";
  // 1.0 until session 9; the bounce read at points of the light's map (bounce.glsl,
  // BOUNCE_LOD_FINER) varies more between the gather's points, which follow the lighting
  // resolution (one per 4 x 4 lighting texels): 1.012 here since (`marble compare` of the two at
  // 128²: relative RMSE 0.093 on main, 0.095 after).
  EXPECT_LT(diff, 1.1) << "mean difference in 8-bit levels";
  // Silhouettes: no rim of pixels turns dark or light where the half-resolution blur has no
  // coverage (the outline alone is about 800 pixels here); isolated pixels at shadow edges
  // and depth jumps may differ.
  int changed = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x)
      if (glm::length(pixel(full, x, y) - pixel(half, x, y)) > 0.25f) ++changed;
  EXPECT_LT(changed, 128 * 128 / 100);
}

TEST_F(PassFixture, HdrReadbackIsTheLastFrameLinear) {
  renderer.setMesh(builtinMesh("sphere"));
  Scene s = marbleScene("sphere", 48);
  renderImage(renderer, s);
  const ImageRGBF hdr = renderer.readHdr();
  ASSERT_EQ(hdr.width, 48);
  ASSERT_EQ(hdr.height, 48);
  // Centre: lit stone, linear and positive; corner: background, zero light.
  const size_t centre = (24 * 48 + 24) * 3, corner = 0;
  EXPECT_GT(hdr.pixels[centre + 1], 0.05f);
  EXPECT_EQ(hdr.pixels[corner], 0.0f);
  // Reading does not disturb the next frame's caching.
  renderImage(renderer, s);
  EXPECT_FALSE(renderer.passTimes(true).ran[Pass::Lighting]);
}

TEST(ProgramVariants, CompilesEachSetOfDefinesOnceAndReportsErrorsByFile) {
  glContext();
  const auto dir = std::filesystem::temp_directory_path() / "marble_variants_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "variant_test.frag.glsl") << "#version 450 core\nout vec4 c;\nvoid main() {\n"
                                                   "#ifdef BROKEN\n  c = undefined_name;\n#else\n  c = vec4(VALUE);\n#endif\n}\n";
  std::ofstream(dir / "variant_test.vert.glsl") << "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
  ShaderLibrary library(dir.string());
  gl::ProgramVariants variants(library, {{GL_VERTEX_SHADER, "variant_test.vert.glsl"},
                                         {GL_FRAGMENT_SHADER, "variant_test.frag.glsl"}});
  const GLuint a = variants.get({"VALUE 1.0"}).id();
  const GLuint b = variants.get({"VALUE 0.5"}).id();
  EXPECT_NE(a, b);
  EXPECT_EQ(variants.get({"VALUE 1.0"}).id(), a) << "kept, not rebuilt";
  EXPECT_EQ(variants.compiledCount(), 2u);
  try {
    variants.get({"BROKEN 1"});
    FAIL() << "a broken variant must throw";
  } catch (const gl::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("variant_test.frag.glsl"), std::string::npos) << e.what();
  }
  EXPECT_EQ(variants.compiledCount(), 2u);
  // The per-frame path: a number finds the program; the defines are built only once.
  int built = 0;
  const auto make = [&] {
    ++built;
    return std::vector<std::string>{"VALUE 0.5"};
  };
  EXPECT_EQ(variants.get(7u, make).id(), b) << "the key leads to the program of its defines";
  EXPECT_EQ(variants.get(7u, make).id(), b);
  EXPECT_EQ(built, 1);
  EXPECT_EQ(variants.compiledCount(), 2u);
  std::filesystem::remove_all(dir);
}
