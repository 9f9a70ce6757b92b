#include "marble/render/pass_cache.h"

#include <cstring>

namespace marble {
namespace {

// Bit for bit: a matrix recomputed from the same values is the same bits, and a pass re-run
// from other bits could round differently.
bool sameMatrix(const glm::mat4& a, const glm::mat4& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

bool isMarble(const FrameInputs& f) { return f.scene.render.mode == RenderMode::Marble; }

}  // namespace

bool sameInput(PassInput i, const FrameInputs& a, const FrameInputs& b) {
  const RenderSettings &ra = a.scene.render, &rb = b.scene.render;
  switch (i) {
    case PassInput::LightMesh:
    case PassInput::CameraMesh:
    case PassInput::EnvironmentMap:
    case PassInput::TurbulenceGrid: return true;  // by revision (PassCache)
    case PassInput::Model: return sameMatrix(a.model, b.model);
    case PassInput::LightMatrices:
      // `direction` is set for a directional light only (view_setup.cpp leaves it unset otherwise).
      return sameMatrix(a.light.viewProj, b.light.viewProj) && a.light.position == b.light.position &&
             a.light.directional == b.light.directional &&
             (!a.light.directional || a.light.direction == b.light.direction) && a.light.near == b.light.near &&
             a.light.far == b.light.far;
    case PassInput::CameraMatrices: return sameMatrix(a.camera.viewProj, b.camera.viewProj);
    case PassInput::FrameSize: return a.width == b.width && a.height == b.height;
    case PassInput::Light: return a.scene.light == b.scene.light;
    case PassInput::Camera: return a.scene.camera == b.scene.camera;
    case PassInput::Mode: return ra.mode == rb.mode;
    case PassInput::Environment:
      return ra.environment == rb.environment && ra.environment_intensity == rb.environment_intensity &&
             ra.environment_rotation_deg == rb.environment_rotation_deg;
    case PassInput::SubsurfaceResolution: return ra.subsurface_resolution == rb.subsurface_resolution;
    case PassInput::ObjectSize: return a.scene.mm_per_unit == b.scene.mm_per_unit;
    case PassInput::SeenPattern:
      return isMarble(a) == isMarble(b) && a.seenAttenuation == b.seenAttenuation &&
             (a.seenAttenuation == 0.0f || a.scene.material.ior == b.scene.material.ior);
    case PassInput::Scene: return a.scene == b.scene;
  }
  return false;
}

bool sameButPattern(const FrameInputs& a, const FrameInputs& b) {
  for (size_t i = kRendererStateInputs; i < kPassInputCount; ++i) {
    const auto input = static_cast<PassInput>(i);
    if (input != PassInput::SeenPattern && input != PassInput::Scene && !sameInput(input, a, b)) return false;
  }
  // The scene but its material; the material's groups that anything but the pattern reads (a
  // group the pattern shares with another reader, such as the base colour, is compared).
  Scene withB = a.scene;
  withB.material = b.scene.material;
  if (!(withB == b.scene)) return false;
  const GroupSet others = groupsRead(~static_cast<uint32_t>(kAlbedoPassBit), a.scene.render.mode);
  return sameGroups(a.scene.material, b.scene.material, others);
}

bool PassCache::current(Pass p, const FrameInputs& now) const {
  // The groups of the frame's mode: a pass that does not declare the mode reads the same
  // groups in every mode it runs in (tests/pass_list_test.cpp).
  return currentButMaterial(p, now) &&
         sameGroups(made_[p]->inputs.scene.material, now.scene.material, passGroups(p, now.scene.render.mode));
}

bool PassCache::currentButMaterial(Pass p, const FrameInputs& now) const {
  const std::optional<Record>& r = made_[p];
  if (!r) return false;
  const PassDecl& d = passDecl(p);
  for (size_t i = 0; i < kPassInputCount; ++i) {
    if ((d.inputs & (1u << i)) == 0) continue;
    if (i < kRendererStateInputs ? r->revisions[i] != revision_[i]
                                 : !sameInput(static_cast<PassInput>(i), r->inputs, now))
      return false;
  }
  const PassSet reads = passReads(p, now.scene);
  for (const PassDecl& q : passList())
    if ((reads & passBit(q.pass)) != 0 && r->generations[q.pass] != generation_[q.pass]) return false;
  return true;
}

void PassCache::made(Pass p, const FrameInputs& now) {
  ++generation_[p];
  made_[p] = Record{now, revision_, generation_};
}

void PassCache::changed(PassInput state) {
  ++revision_[static_cast<size_t>(state)];
  ++stateRevision_;
}

void PassCache::forget() {
  for (auto& r : made_.values) r.reset();
  ++stateRevision_;
}

}  // namespace marble
