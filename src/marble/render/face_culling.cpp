#include "marble/render/face_culling.h"

#include "marble/render/screen_cull.h"

namespace marble {

GLenum facesHiddenFromEye(SurfaceWinding winding, const glm::mat4& modelViewProj, const glm::vec3& boundsMin,
                             const glm::vec3& boundsMax) {
  if (winding == SurfaceWinding::Open) return GL_NONE;
  // Beyond the near plane: z > -w in GL's clip space (depth range -1..1). The plane's test is
  // linear in the object-space point, so the box's corners decide for all of it.
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? boundsMax.x : boundsMin.x, (corner & 2) ? boundsMax.y : boundsMin.y,
                      (corner & 4) ? boundsMax.z : boundsMin.z);
    const glm::vec4 clip = modelViewProj * glm::vec4(p, 1.0f);
    if (!(clip.w > 0.0f && clip.z > -clip.w)) return GL_NONE;
  }
  // GL's projections turn the right-handed eye space into a left-handed clip space (det < 0):
  // there a face wound counter-clockwise (the mesh's outward sense) appears counter-clockwise on
  // screen, GL's front face, when it faces the eye.
  const float det = glm::determinant(modelViewProj);
  if (det == 0.0f) return GL_NONE;
  const bool screenKeepsSense = det < 0.0f;
  const bool outward = winding == SurfaceWinding::Outward;
  return outward == screenKeepsSense ? GL_BACK : GL_FRONT;
}

void cullFacesHiddenFromEye(bool enabled, const GpuMesh& mesh, const glm::mat4& modelViewProj) {
  const GLenum hidden =
      enabled ? facesHiddenFromEye(mesh.winding(), modelViewProj, mesh.boundsMin(), mesh.boundsMax()) : GLenum{GL_NONE};
  if (hidden == GL_NONE) return;
  glEnable(GL_CULL_FACE);
  glCullFace(hidden);
}

void HiddenFaceDraw::prepare(bool enabled, bool onCpu, const GpuMesh& mesh, const glm::mat4& modelViewProj, int width,
                             int height) {
  const GLenum hidden =
      enabled ? facesHiddenFromEye(mesh.winding(), modelViewProj, mesh.boundsMin(), mesh.boundsMax()) : GLenum{GL_NONE};
  subset_ = false;
  if (hidden == GL_NONE) return;
  glEnable(GL_CULL_FACE);
  glCullFace(hidden);
  if (!onCpu) return;
  uint32_t* kept = mesh.mapSubset();
  if (!kept) return;  // not mapped: the whole mesh, GL culls alone
  keptTriangles_ = trianglesGlMayDraw(mesh.screenCullMesh(), modelViewProj, width, height,
                                      hidden == GL_BACK ? CulledSense::Clockwise : CulledSense::CounterClockwise, kept,
                                      scratch_);
  mesh.unmapSubset();
  subset_ = true;
}

void HiddenFaceDraw::draw(const GpuMesh& mesh) const {
  if (subset_)
    mesh.drawSubset(3 * keptTriangles_);
  else
    mesh.draw();
}

}  // namespace marble
