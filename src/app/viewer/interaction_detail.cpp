#include "interaction_detail.h"

#include <string>

#include "marble/core/error.h"
#include "marble/render/mesh_detail.h"

namespace marble {

InteractionDetailSetting parseInteractionDetail(std::string_view name) {
  if (name == "auto") return InteractionDetailSetting::Auto;
  if (name == "on") return InteractionDetailSetting::On;
  if (name == "off") return InteractionDetailSetting::Off;
  throw InputError("--interaction-detail", "", "expected auto, on or off, got \"" + std::string(name) + "\"");
}

std::string_view interactionDetailName(InteractionDetailSetting setting) {
  switch (setting) {
    case InteractionDetailSetting::Auto: return "auto";
    case InteractionDetailSetting::On: return "on";
    case InteractionDetailSetting::Off: return "off";
  }
  return "auto";
}

bool interactionDetailApplies(InteractionDetailSetting setting, size_t triangles) {
  if (setting == InteractionDetailSetting::Auto) return triangles > kInteractionMinTriangles;
  return setting == InteractionDetailSetting::On;
}

Renderer::MeshDetail InteractionDetailTracker::next(InteractionDetailSetting setting, size_t triangles,
                                                    const Camera& camera, const glm::mat4& model) {
  const bool moved = seen_ && (!(camera == lastCamera_) || model != lastModel_);
  seen_ = true;
  lastCamera_ = camera;
  lastModel_ = model;
  return moved && interactionDetailApplies(setting, triangles) ? Renderer::MeshDetail::Interaction
                                                               : Renderer::MeshDetail::Full;
}

}  // namespace marble
