#pragma once
// Interaction detail, as scan and CAD viewers and game engines do it, in two independent settings:
// - the mesh: while the camera or the object moves, the camera's passes draw a simplified copy
//   of the mesh (Renderer::MeshDetail::Interaction, render/mesh_detail.h);
// - the resolution: while the camera, the object or the light moves, every pass draws at a
//   fraction of the view's width and height, stretched to the view (dynamic resolution,
//   Renderer::setResolutionScale);
// - the light's maps: while the object or the light moves (the light's pass re-runs every frame
//   then), they are drawn at the resolution's share of their size (Renderer::LightMapDetail);
//   while only the camera moves they stay as they are, full-size and not redrawn.
// The first frame in which nothing moved draws the full mesh at the full resolution, and is then
// exactly the frame a fresh renderer would draw (tests/mesh_detail_gl_test.cpp,
// tests/resolution_scale_gl_test.cpp). Edits of the material are not "moving": they draw the
// full picture.
#include <cstddef>
#include <string_view>

#include <glm/glm.hpp>

#include "marble/render/mesh_detail.h"
#include "marble/render/renderer.h"
#include "marble/scene/scene.h"

namespace marble {

// auto (default): on for meshes above kInteractionMinTriangles; on; off.
enum class InteractionDetailSetting { Auto, On, Off };
InteractionDetailSetting parseInteractionDetail(std::string_view name);  // throws InputError
std::string_view interactionDetailName(InteractionDetailSetting setting);
bool interactionDetailApplies(InteractionDetailSetting setting, size_t triangles);

// The resolution while moving: kDefaultInteractionResolution (render/mesh_detail.h) unless told.
float parseInteractionResolution(float scale);  // throws InputError outside [kMinResolutionScale, 1]

// What one frame draws.
struct InteractionFrame {
  Renderer::MeshDetail mesh = Renderer::MeshDetail::Full;
  float resolutionScale = 1.0f;
  Renderer::LightMapDetail lightMaps = Renderer::LightMapDetail::Full;
  bool operator==(const InteractionFrame&) const = default;
};

// Remembers the last frame's camera, light and model; says which detail this frame draws.
class InteractionDetailTracker {
public:
  // `reducedLightMaps`: the light's maps at interaction detail while the object or light moves.
  InteractionFrame next(InteractionDetailSetting meshSetting, float movingResolution, bool reducedLightMaps,
                        size_t triangles, const Camera& camera, const Light& light, const glm::mat4& model);

private:
  bool seen_ = false;
  Camera lastCamera_{};
  Light lastLight_{};
  glm::mat4 lastModel_{1.0f};
};

}  // namespace marble
