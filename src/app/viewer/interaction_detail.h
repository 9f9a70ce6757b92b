#pragma once
// Interaction detail, as scan and CAD viewers do it: while the camera or the object moves, the
// camera's passes draw a simplified copy of the mesh (Renderer::MeshDetail::Interaction,
// render/mesh_detail.h); the first frame in which neither moved draws the full mesh, and is
// then exactly the frame a fresh renderer would draw (tests/mesh_detail_gl_test.cpp). Edits
// of the material or the light are not "moving": they draw the full mesh.
#include <cstddef>
#include <string_view>

#include <glm/glm.hpp>

#include "marble/render/renderer.h"
#include "marble/scene/scene.h"

namespace marble {

// auto (default): on for meshes above kInteractionMinTriangles; on; off.
enum class InteractionDetailSetting { Auto, On, Off };
InteractionDetailSetting parseInteractionDetail(std::string_view name);  // throws InputError
std::string_view interactionDetailName(InteractionDetailSetting setting);
bool interactionDetailApplies(InteractionDetailSetting setting, size_t triangles);

// Remembers the last frame's camera and model; says which detail this frame draws.
class InteractionDetailTracker {
public:
  Renderer::MeshDetail next(InteractionDetailSetting setting, size_t triangles, const Camera& camera,
                            const glm::mat4& model);

private:
  bool seen_ = false;
  Camera lastCamera_{};
  glm::mat4 lastModel_{1.0f};
};

}  // namespace marble
