#include "marble/render/pass_list.h"

#include "marble/render/stage_pass.h"

namespace marble {
namespace {

constexpr InputSet in(PassInput i) { return inputBit(i); }
using I = PassInput;
constexpr PassSet of(Pass p) { return passBit(p); }

// clang-format off
constexpr PassDecl kPasses[] = {
    {Pass::LightDepth, "light_depth", "light depth",
     "Distance and entry cosine of the mesh seen from the light, and its depth (shadows, thickness).",
     in(I::LightMesh) | in(I::Model) | in(I::LightMatrices), 0, 0, 0, false},
    {Pass::Geometry, "geometry", "geometry",
     "G-buffer: normal and depth of the mesh seen from the camera (marble mode: also the normal bent by Cycles' "
     "valid-reflection rule, for the post pass's reflection terms).",
     in(I::CameraMesh) | in(I::Model) | in(I::CameraMatrices) | in(I::FrameSize) | in(I::Mode), 0, 0, 0, false},
    {Pass::Albedo, "albedo", "albedo",
     "The marble pattern, once per visible pixel (marble mode evaluates it in the post pass, into the same texture).",
     in(I::Model) | in(I::CameraMatrices) | in(I::SeenPattern) | in(I::TurbulenceGrid), kAlbedoPassBit, 0,
     of(Pass::Geometry), false},
    {Pass::BlurDepth, "blur_depth", "blur depth",
     "The depth at the blur's half resolution, so that the lighting and the blur shade only the object.",
     in(I::FrameSize) | in(I::SubsurfaceResolution), 0, 0, of(Pass::Geometry), false},
    {Pass::Bounce, "bounce", "bounce",
     "Marble mode: light bounced inside the object (from the light's reflective shadow map), gathered at a quarter "
     "of the lighting pass's texels, and the further bounces from a radiosity over the whole surface (solved on the "
     "CPU when the light moves) added to it; the lighting pass upsamples their sum.",
     in(I::Light) | in(I::LightMatrices) | in(I::CameraMatrices) | in(I::FrameSize) | in(I::SubsurfaceResolution),
     kBouncePassBit, 0, of(Pass::LightDepth) | of(Pass::Geometry), false},
    {Pass::Lighting, "lighting", "lighting",
     "Screen-space shading of the object's pixels; marble mode: the light entering the stone, at the blur's "
     "resolution.",
     in(I::Light) | in(I::LightMatrices) | in(I::Camera) | in(I::CameraMatrices) | in(I::Mode) | in(I::Environment) |
         in(I::EnvironmentMap) | in(I::SubsurfaceResolution) | in(I::ObjectSize),
     kLightingPassBit, 0,
     of(Pass::LightDepth) | of(Pass::Geometry) | of(Pass::Albedo) | of(Pass::BlurDepth) | of(Pass::Bounce), false},
    {Pass::SubsurfaceBlur, "subsurface_blur", "subsurface blur",
     "Screen-space diffusion of the light under the surface (marble mode; half or full resolution).",
     in(I::Camera) | in(I::CameraMatrices) | in(I::SubsurfaceResolution) | in(I::ObjectSize), kBlurPassBit, 0,
     of(Pass::Geometry) | of(Pass::BlurDepth) | of(Pass::Lighting), false},
    {Pass::Post, "post", "post",
     "Marble mode: blurred light x albedo + reflections, tone mapping; the diffuse part from the pattern (evaluated "
     "here), the stored albedo or, when neither the light nor the albedo changed, stored. Other modes: pass-through.",
     in(I::Light) | in(I::LightMatrices) | in(I::Camera) | in(I::CameraMatrices) | in(I::Model) | in(I::Mode) |
         in(I::Environment) | in(I::EnvironmentMap) | in(I::ObjectSize) | in(I::SeenPattern) | in(I::Scene),
     kPostPassBit, kAlbedoPassBit,
     of(Pass::LightDepth) | of(Pass::Geometry) | of(Pass::Albedo) | of(Pass::Lighting) | of(Pass::SubsurfaceBlur),
     true},
    {Pass::Stage, "stage", "stage",
     "Backdrop and ground around the object (and, when the mesh or model changed, the ground's contact map).",
     in(I::Model) | in(I::Light) | in(I::LightMatrices) | in(I::Camera) | in(I::CameraMatrices) | in(I::Environment) |
         in(I::EnvironmentMap) | in(I::Scene),
     0, 0, of(Pass::LightDepth) | of(Pass::Geometry) | of(Pass::Post), true},
    {Pass::Fxaa, "fxaa", "fxaa",
     "Antialiasing (FXAA) of the displayed picture, on the tiles the object can cover.",
     in(I::Model) | in(I::CameraMatrices) | in(I::Scene), 0, 0, of(Pass::Post) | of(Pass::Stage), true},
    {Pass::Floor, "floor", "floor",
     "The mesh once, flat-shaded: the cheapest frame (benchmarks).",
     in(I::CameraMesh) | in(I::Model) | in(I::CameraMatrices) | in(I::Light) | in(I::Scene), kFloorPassBit, 0, 0,
     true},
};
// clang-format on
static_assert(std::size(kPasses) == kPassCount);

constexpr bool inEnumOrder() {
  for (size_t i = 0; i < kPassCount; ++i)
    if (static_cast<size_t>(kPasses[i].pass) != i) return false;
  return true;
}
static_assert(inEnumOrder(), "passList() is indexed by Pass");

constexpr const char* kInputLabels[] = {
    "the light's mesh and maps' size", "the camera's mesh (full or interaction copy)", "the environment map",
    "the turbulence grid setting", "the model transform", "the light's matrices", "the camera's matrices",
    "the frame size", "the light", "the camera", "the render mode", "the environment", "the subsurface resolution",
    "the object's size (mm per unit)", "how the pattern is seen (marble: through the polish)", "the rest of the scene",
};
static_assert(std::size(kInputLabels) == kPassInputCount);

}  // namespace

std::span<const PassDecl> passList() { return kPasses; }

const PassDecl& passDecl(Pass p) { return kPasses[static_cast<size_t>(p)]; }

const char* passInputLabel(PassInput i) { return kInputLabels[static_cast<size_t>(i)]; }

bool passInFrame(Pass p, const Scene& scene) {
  const RenderSettings& r = scene.render;
  if (r.mode == RenderMode::Floor) return p == Pass::Floor;
  const bool marble = r.mode == RenderMode::Marble;
  switch (p) {
    case Pass::Albedo: return !marble && modeShowsAlbedo(r.mode);
    case Pass::BlurDepth: return marble && r.subsurface_resolution == SubsurfaceResolution::Half;
    case Pass::Bounce: return marble;
    case Pass::SubsurfaceBlur: return marble;
    case Pass::Stage: return sceneHasStage(scene);
    case Pass::Fxaa: return r.antialias == Antialias::Fxaa;
    case Pass::Floor: return false;
    default: return true;
  }
}

GroupSet passGroups(Pass p, RenderMode mode) {
  const PassDecl& d = passDecl(p);
  return groupsRead(d.params | (mode == RenderMode::Marble ? d.marbleParams : 0u), mode);
}

PassSet passReads(Pass p, const Scene& scene) {
  PassSet s = 0;
  for (const PassDecl& q : kPasses)
    if ((passDecl(p).reads & passBit(q.pass)) != 0 && passInFrame(q.pass, scene)) s |= passBit(q.pass);
  return s;
}

std::string passInputsText(Pass p, const Scene& scene) {
  const PassDecl& d = passDecl(p);
  std::string list;
  auto add = [&list](const std::string& item) { list += (list.empty() ? "" : ", ") + item; };
  for (size_t i = 0; i < kPassInputCount; ++i)
    if ((d.inputs & (1u << i)) != 0) add(kInputLabels[i]);
  const GroupSet groups = passGroups(p, scene.render.mode);
  for (const ParamGroupDesc& g : paramGroups())
    if ((groups & groupBit(g.id)) != 0) add(std::string("the parameters of ") + g.title);
  std::string after;
  const PassSet reads = passReads(p, scene);
  for (const PassDecl& q : kPasses)
    if ((reads & passBit(q.pass)) != 0) after += (after.empty() ? "" : ", ") + std::string(q.label);
  if (d.everyFrame)
    return "Runs in every frame that is drawn (a frame in which nothing changed is not); reads " + list +
           (after.empty() ? "" : ", and the output of " + after) + ".";
  return "Re-runs when one of these changed: " + list + (after.empty() ? "" : "; or after " + after + " re-ran") + ".";
}

}  // namespace marble
