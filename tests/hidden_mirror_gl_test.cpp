// The mirror image of a glowing face hidden from the camera (shaders/hidden_mirror.glsl;
// docs/quality.md, "Twenty-second session: the mirror image of the surfaces the camera cannot
// see"). The self-reflection test's plate and wall (self_reflection_gl_test.cpp), lit from behind
// the wall: a 4 mm wall, the light crossing it from its far side, so that its face toward the
// plate glows with the light carried through it (the transmission), and the plate, in the wall's
// shadow, mirrors that face toward a camera low over it (N.V 0.45). With the camera's view of the
// face open, the screen-space march finds it on screen and the post pass mirrors it; with a bar
// hung between the camera and the face (its view of the plate's point p left open), the march
// passes behind the bar, and only the march against the light's exit layer can find the face.
// The plate at p shows the same mirror image either way, to within the two estimates of the
// face's light (the camera sees the transmission's ring gather, the exit layer's march the
// straight chord: the same on a flat slab) and what the bar takes from p's other light.
// Session 19's estimate at the step's middle from the one-layer map gave 0.03 of it on such a
// scene: the air between the parts counted as stone.
// Measured: p open 0.0199 (F x the face's light read off the same picture: 0.0199, so p's light
// is the mirror image), hidden 0.0177: 0.89 (allowed 0.75-1.33). Control, rebuilt by hand
// (hidden_mirror returning nothing, as main): hidden 0, failing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>

#include <unistd.h>

#include "box_mesh.h"
#include "fresnel_dielectric.h"
#include "gl_support.h"
#include "image_probe.h"
#include "principled_stone.h"
#include "marble/gl/shader_library.h"
#include "marble/mesh/vertex_normals.h"

using namespace marble;
using namespace marble::test;

namespace {

using thin_plate::kPlate;
using thin_plate::kPlateTop;
using thin_plate::kWall;

constexpr float kD = 0.45f;       // p's distance from the wall's face
constexpr float kCosView = 0.45f;  // N.V at p
constexpr float kThinWall = 0.04f;  // 4 mm at 100 mm per unit

glm::vec3 pointP() { return {kWall + kD, kPlateTop, 0.0f}; }
glm::vec3 cameraPosition() {
  const float sinView = std::sqrt(1.0f - kCosView * kCosView);
  return pointP() + 1.5f * glm::vec3(sinView, kCosView, 0.0f);
}
// Where p's mirror ray meets the wall's face.
glm::vec3 pointW() {
  const float sinView = std::sqrt(1.0f - kCosView * kCosView);
  return {kWall, kPlateTop + kD * kCosView / sinView, 0.0f};
}

// The plate, the thin wall on its end (its face toward the plate at x = kWall), and, where
// `hidden`, a bar across the middle of the camera's line of sight to the wall's face at w, in the
// wall's shadow (beyond the first part along the light).
Mesh scene(bool hidden, bool woundInward = false) {
  Mesh m;
  addBox(m, {kWall - kThinWall, kPlateTop, -1.0f}, {kWall, 1.0f, 1.0f});
  addBox(m, {kWall, kPlateTop - kPlate, -1.0f}, {1.0f, kPlateTop, 1.0f});
  if (hidden) {
    const glm::vec3 mid = 0.5f * (cameraPosition() + pointW());
    addBox(m, {mid.x - 0.05f, mid.y - 0.05f, -1.0f}, {mid.x + 0.05f, mid.y + 0.05f, 1.0f});
  }
  if (woundInward)  // every triangle turned: its normals, computed from the winding, point in
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3) std::swap(m.indices[i + 1], m.indices[i + 2]);
  computeVertexNormals(m, 60.0f);  // flat faces
  return m;
}

Scene view() {
  Scene s;
  s.mesh = "test:hidden-mirror";
  s.mm_per_unit = 100.0f;
  s.render.width = s.render.height = 256;
  s.render.mode = RenderMode::Marble;
  s.render.environment = Environment::None;
  s.camera.position = cameraPosition();
  s.camera.target = pointP();
  s.camera.fov_y_deg = 40;
  s.light.type = LightType::Directional;
  s.light.position = {-1.0f, 0.2f, 0.0f};  // from behind the wall, a little from above
  s.light.intensity = 1.0f;
  s.material = test::principledStone(glm::vec3(0.8f));
  return s;
}

}  // namespace

TEST(HiddenMirror, APlateMirrorsTheGlowingFaceBehindAPart) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene s = view();
  const HdrPair img = renderHdrPair(s, scene(false), scene(true));
  const float open = linearRgbAround(img.first, s, pointP()).g;
  const float hidden = linearRgbAround(img.second, s, pointP()).g;
  const float face = linearRgbAround(img.first, s, pointW()).g;
  const float predicted = static_cast<float>(fresnelDielectric(kCosView, s.material.ior)) * face;
  std::cout << "[          ] p open " << open << ", hidden " << hidden << "; F x the face " << predicted
            << ": hidden / open " << hidden / open << "\n";
  ASSERT_GT(predicted, 0.5f * open) << "the open view's light at p is mostly the face's mirror image";
  EXPECT_GT(hidden / open, 0.75f);
  EXPECT_LT(hidden / open, 1.33f);
}

// The same scene wound inward (the teapot of the reference scenes is): the light's layers take each
// surface's outside from the mesh's signed volume (GpuMesh::woundInward), so the face is found as
// before. Measured: the same figures. Control, rebuilt by hand (the layers' facing not turned,
// u_outward 1): hidden 0, failing -- the exits lay before the entries, as on teapot-back.
TEST(HiddenMirror, AMeshWoundInwardMirrorsTheSameFace) {
  HeadlessContext& context = glContext();
  (void)context;
  const Scene s = view();
  const HdrPair img = renderHdrPair(s, scene(true), scene(true, true));
  const float outward = linearRgbAround(img.first, s, pointP()).g;
  const float inward = linearRgbAround(img.second, s, pointP()).g;
  std::cout << "[          ] p hidden, wound outward " << outward << ", inward " << inward << "\n";
  ASSERT_GT(outward, 0.0f);
  EXPECT_NEAR(inward / outward, 1.0f, 0.05f);
}

// A part's side, edge-on to the light: a block 15 mm thick standing behind the plate's far end
// (its face toward the plate at x = kWall, where the wall's was; its top 6 mm above w), lit from
// straight above, so that in the light's view its face toward the plate has no area: the light
// enters the block's top and the face glows with what is carried down to each depth. The mirror
// ray from p enters the block through that face, beside the block in the light's view, without
// crossing an exit face: the side hit of hidden_mirror.glsl. The block shadows nothing of p (light
// from above), so its image at p is p's light with the block less p's light without, both with the
// bar hiding the face from the camera; the reference is F x the face's light as the camera sees it
// at w (the open picture). Measured: hidden 0.0161, F x the face 0.0259: 0.62 (allowed 0.4-1.5;
// the two estimates of a side face's glow differ: the camera's transmission there, the march's
// chord from the entry down to its point inside, up to a step past the face). The open picture's
// difference at p is 0.101, most of it not the mirror image (the block's other light on p).
// Control, rebuilt by hand (the side hit returning nothing, as main): hidden 0.00098, 0.04, failing.
namespace {

// The block's top above w: w's depth along the light, 6 mm; the march's ray rises 0.5 mm per mm
// toward the block, so it stays inside for 12 mm, more than its step there (~7 layer texels,
// 9.5 mm, at p's distance from the face): a side hit needs a point inside the part (an exit face
// is found between two points). With the top 2 mm above w the step leapt over the corner.
constexpr float kBlockAbove = 0.06f;
// Thicker than that step, for the same reason.
constexpr float kBlockThick = 0.15f;

Mesh blockScene(bool block, bool hidden) {
  Mesh m;
  const float y = pointW().y;
  if (block) addBox(m, {kWall - kBlockThick, kPlateTop, -1.0f}, {kWall, y + kBlockAbove, 1.0f});
  addBox(m, {kWall, kPlateTop - kPlate, -1.0f}, {1.0f, kPlateTop, 1.0f});
  if (hidden) {
    const glm::vec3 mid = 0.5f * (cameraPosition() + pointW());
    addBox(m, {mid.x - 0.05f, mid.y - 0.05f, -1.0f}, {mid.x + 0.05f, mid.y + 0.05f, 1.0f});
  }
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace

TEST(HiddenMirror, APartsSideEdgeOnToTheLightIsMirrored) {
  HeadlessContext& context = glContext();
  (void)context;
  Scene s = view();
  s.light.position = {0.0f, 1.0f, 0.0f};  // straight down
  float face = 0.0f;
  auto blockLight = [&](bool hidden) {
    const HdrPair img = renderHdrPair(s, blockScene(true, hidden), blockScene(false, hidden));
    if (!hidden) face = linearRgbAround(img.first, s, pointW()).g;
    return linearRgbAround(img.first, s, pointP()).g - linearRgbAround(img.second, s, pointP()).g;
  };
  const float open = blockLight(false), hidden = blockLight(true);
  const float predicted = static_cast<float>(fresnelDielectric(kCosView, s.material.ior)) * face;
  std::cout << "[          ] the wall at p: open " << open << ", hidden " << hidden << "; F x the face " << predicted
            << ": hidden / (F x the face) " << hidden / predicted << "\n";
  ASSERT_GT(predicted, 0.0f);
  EXPECT_GT(hidden / predicted, 0.4f);
  EXPECT_LT(hidden / predicted, 1.5f);
}

// The hidden face's own indirect light (hidden_mirror.glsl, "the face's indirect light", session
// 23): a face hidden from the camera sends the plate what the bounces bring it as well as its glow,
// and the lighting pass takes that as p's own diffuse bounce. The stone here does not glow
// (translucency 0) and a low wall leaves a block standing beyond the plate's far end lit, to the
// side of the camera's line of sight to p: the block's light reaches both the wall's face and p,
// diffusely, and is all the face sends. The mirror image is isolated by its dependence on the view
// (as in self_reflection_gl_test.cpp): p seen at N.V 0.2 and 0.45, the difference of p's light
// between the two views is (F(0.2) - F(0.45)) x the light the face sends along each mirror ray,
// while p's diffuse light is the same from both. Hidden: two thin bars, both in both views, each
// across one view's line of sight to the face where its mirror ray meets it (and across neither
// view's line of sight to p); open: no bars. With the face's indirect light the hidden difference
// is F's difference x p's bounce, the open one F's difference x the face's (the post pass mirrors
// the face's blurred light): measured 0.0151 against 0.0122, 1.24 -- p receives 1.24x the face's
// bounce here, the approximation's error in this geometry. Since session 25 the further bounces come
// from the world-space radiosity (further_radiosity.h), which gives the face, lit by the block,
// more of them than p in the wall's shadow: 0.78 with its grid at 32 cells a side, 0.72 at 48 (the
// approximation's error the other way; allowed 0.6-1.5). Control, rebuilt by hand (the face's
// indirect light left out, as before session 23): hidden -0.0002, -0.01, failing.
namespace {

constexpr float kFarBlock = 1.4f;  // the far block's face toward the wall
// A low wall: its shadow (the light falls 0.2 per unit) leaves the block lit from y = -0.46 up and
// still covers p (y = -0.6) and the face where p's mirror rays meet it (y -0.51 and -0.37).
constexpr float kLowWallTop = -0.2f;
constexpr float kBarX = 1.2f;  // the bars' place along x, between p and the cameras

glm::vec3 cameraAt(float cosView) {
  const float sinView = std::sqrt(1.0f - cosView * cosView);
  return pointP() + 1.5f * glm::vec3(sinView, cosView, 0.0f);
}
glm::vec3 faceAt(float cosView) {
  const float sinView = std::sqrt(1.0f - cosView * cosView);
  return {kWall, kPlateTop + kD * cosView / sinView, 0.0f};
}
// Where the camera's line of sight to the face crosses x = kBarX.
float barHeight(float cosView) {
  const glm::vec3 c = cameraAt(cosView), f = faceAt(cosView);
  return c.y + (f.y - c.y) * (c.x - kBarX) / (c.x - f.x);
}

Mesh litBlockScene(bool bars) {
  Mesh m;
  addBox(m, {kWall - kThinWall, kPlateTop, -1.0f}, {kWall, kLowWallTop, 1.0f});
  addBox(m, {kWall, kPlateTop - kPlate, -1.0f}, {1.0f, kPlateTop, 1.0f});
  addBox(m, {kFarBlock, kPlateTop, -1.0f}, {kFarBlock + 0.1f, 1.0f, -0.25f});  // beside the lines of sight
  if (bars)
    for (float cosView : {0.2f, kCosView}) {
      const float y = barHeight(cosView);
      addBox(m, {kBarX - 0.03f, y - 0.025f, -1.0f}, {kBarX + 0.03f, y + 0.025f, 1.0f});
    }
  computeVertexNormals(m, 60.0f);
  return m;
}

}  // namespace

TEST(HiddenMirror, TheHiddenFaceAlsoSendsItsIndirectLight) {
  HeadlessContext& context = glContext();
  (void)context;
  auto seen = [](float cosView) {
    Scene s = view();
    s.camera.position = cameraAt(cosView);
    s.material.translucency = 0.0f;  // no glow: the face sends only what the bounces bring it
    const HdrPair img = renderHdrPair(s, litBlockScene(false), litBlockScene(true));
    return std::pair<float, float>(linearRgbAround(img.first, s, pointP()).g, linearRgbAround(img.second, s, pointP()).g);
  };
  const auto low = seen(0.2f), high = seen(kCosView);
  const float open = low.first - high.first, hidden = low.second - high.second;
  std::cout << "[          ] p at N.V 0.2 / 0.45: open " << low.first << " / " << high.first << ", hidden " << low.second
            << " / " << high.second << ": the view's difference open " << open << ", hidden " << hidden
            << ", hidden / open " << hidden / open << "\n";
  ASSERT_GT(open, 0.0f);
  EXPECT_GT(hidden / open, 0.6f);
  EXPECT_LT(hidden / open, 1.5f);
}

// The lit face behind the mirror hit (hidden_mirror.glsl, hidden_lit_face_behind; the shader-level
// tests of its decision are mirror_lit_face_gl_test.cpp). A shelf floats over the plate beyond p,
// its underside where p's mirror ray meets it, lit from -x and below (the plate's top and the shelf's
// top and front are not lit directly). The underside rises toward the camera 16 degrees, less than
// the camera's 18.6 degrees above the plate seen from there: the camera cannot see it, and at the
// pixels where the ray meets it the camera sees the shelf's front face, 0.1 in front along the view,
// which the screen march takes for its hit. There the underside's light is what p mirrors: the light
// entering it, I cos(theta) principled_entry (hidden_lit_face_behind). Isolated by rendering the
// same scene with the function's gate closed (a shader folder of the test's own): p's light with it
// less p's light without is the underside's mirror image less the front face's (which the post pass
// mirrors without it; the front face is not lit directly). Without the shelf the two shaders give
// the same picture. Measured: p 0.1792 with, 0.1694 without: 0.0098, 0.24 of F x albedo x the
// underside's entering light (0.0411) at p's 3 x 3 pixels (allowed 0.12-0.6): the mirrored strip is
// a few pixels wide on the plate and the subsurface blur spreads it (not measured further). The gate
// sub-tests, each forced by hand through a shader folder: every pixel of the probe passes the gate
// (the march's hit; R.L > 0, R.V < 0), the gap and the light-entry tests. With the underside turned
// 24 degrees (beyond the camera's elevation there: the camera sees it) the gap test fails on most
// pixels: the march's hit is the underside itself.
// Control, by hand: the gate closed in both renders (hidden_lit_face_behind disabled): 0, failing.
namespace {

constexpr float kShelfReach = 0.3f;   // along the underside, from the shelf's front edge
constexpr float kShelfThick = 0.05f;  // 5 mm
constexpr float kShelfLip = 0.1f;     // the front edge beyond where p's ray meets the underside
constexpr float kShelfTurnDeg = 16.0f;  // the underside's rise toward +x (its normal (sin, -cos))

// Where p's mirror ray meets the underside: 0.3 along the ray.
glm::vec3 pointU() {
  const float sinView = std::sqrt(1.0f - kCosView * kCosView);
  return pointP() + 0.3f * glm::vec3(-sinView, kCosView, 0.0f);
}

// The plate from 0.2 before p (the light, from -x and below, passes its end on the way to the
// underside) and, where `shelf`, the shelf turned about the line through u along z.
Mesh shelfScene(bool shelf) {
  Mesh m;
  addBox(m, {pointP().x - 0.2f, kPlateTop - kPlate, -1.0f}, {1.0f, kPlateTop, 1.0f});
  if (shelf) {
    const glm::vec3 u = pointU();
    const size_t first = m.positions.size();
    addBox(m, {u.x + kShelfLip - kShelfReach, u.y, -1.0f}, {u.x + kShelfLip, u.y + kShelfThick, 1.0f});
    const float a = glm::radians(kShelfTurnDeg), c = std::cos(a), sn = std::sin(a);
    for (size_t i = first; i < m.positions.size(); ++i) {
      const glm::vec3 d = m.positions[i] - u;
      m.positions[i] = u + glm::vec3(c * d.x - sn * d.y, sn * d.x + c * d.y, d.z);
    }
  }
  computeVertexNormals(m, 60.0f);
  return m;
}

// A shader folder whose hidden_mirror.glsl has hidden_lit_face_behind's gate closed; empty if the
// built-in file no longer has the gate's line.
std::filesystem::path gateClosed() {
  const std::string gate = "if (hit.x >= 0 && dot(R, light_vector(P)) > 0.0";
  std::string text = embeddedShaders().at("hidden_mirror.glsl");
  const auto at = text.find(gate);
  if (at == std::string::npos) return {};
  text.replace(at, gate.size(), "if (false && dot(R, light_vector(P)) > 0.0");
  const auto dir = std::filesystem::temp_directory_path() / ("marble-lit-face-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "hidden_mirror.glsl") << text;
  return dir;
}

ImageRGBF renderShelf(const Scene& s, bool shelf, const std::filesystem::path& shaders) {
  Renderer renderer{ShaderLibrary(shaders.string())};  // empty: the built-in shaders
  renderer.setMesh(shelfScene(shelf));
  return renderHdr(renderer, s, glm::mat4(1.0f));
}

}  // namespace

TEST(HiddenMirror, APlateMirrorsTheLitFaceBehindTheHitFace) {
  glContext();
  Scene s = view();
  s.light.position = {-1.0f, -1.0f, 0.0f};  // from -x and below, 45 degrees
  const std::filesystem::path closed = gateClosed();
  ASSERT_FALSE(closed.empty()) << "hidden_mirror.glsl no longer has hidden_lit_face_behind's gate";
  auto atP = [&](bool shelf, const std::filesystem::path& shaders) {
    return linearRgbAround(renderShelf(s, shelf, shaders), s, pointP()).g;
  };
  const float with = atP(true, {}), without = atP(true, closed);
  const float bareWith = atP(false, {}), bareWithout = atP(false, closed);
  std::filesystem::remove_all(closed);
  const float turn = glm::radians(kShelfTurnDeg);
  const float cosTheta = glm::dot(glm::normalize(s.light.position), glm::vec3(std::sin(turn), -std::cos(turn), 0.0f));
  const float m = 1.0f - cosTheta, schlick = m * m * m * m * m;
  const float predicted = static_cast<float>(fresnelDielectric(kCosView, s.material.ior)) * s.material.base_color.g *
                          s.light.intensity * cosTheta * (1.0f - 0.5f * schlick);
  std::cout << "[          ] p with the gate " << with << ", closed " << without << ": the underside's image "
            << with - without << "; F x albedo x its entering light " << predicted << "; no shelf " << bareWith
            << " / " << bareWithout << "\n";
  EXPECT_EQ(bareWith, bareWithout);
  EXPECT_GT((with - without) / predicted, 0.12f);
  EXPECT_LT((with - without) / predicted, 0.6f);
}
