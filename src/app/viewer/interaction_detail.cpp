#include "interaction_detail.h"

#include <cstdio>
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

float parseInteractionResolution(float scale) {
  if (!(scale >= Renderer::kMinResolutionScale && scale <= 1.0f)) {
    char text[64];
    std::snprintf(text, sizeof text, "expected %g to 1, got %g", static_cast<double>(Renderer::kMinResolutionScale),
                  static_cast<double>(scale));
    throw InputError("--interaction-resolution", "", text);
  }
  return scale;
}

InteractionFrame InteractionDetailTracker::next(InteractionDetailSetting meshSetting, float movingResolution,
                                                bool reducedLightMaps, size_t triangles, const Camera& camera, const Light& light,
                                                const glm::mat4& model) {
  // The mesh only matters to the camera's passes; the resolution to every pass, the light's too.
  const bool objectMoved = seen_ && model != lastModel_;
  const bool viewMoved = objectMoved || (seen_ && !(camera == lastCamera_));
  const bool lightMoved = seen_ && !(light == lastLight_);
  seen_ = true;
  lastCamera_ = camera;
  lastLight_ = light;
  lastModel_ = model;
  InteractionFrame f;
  if (viewMoved && interactionDetailApplies(meshSetting, triangles)) f.mesh = Renderer::MeshDetail::Interaction;
  if (viewMoved || lightMoved) f.resolutionScale = movingResolution;
  // The light's maps only where they are redrawn anyway: a camera-only move reuses them as they are.
  if (reducedLightMaps && (objectMoved || lightMoved)) f.lightMaps = Renderer::LightMapDetail::Interaction;
  return f;
}

}  // namespace marble
