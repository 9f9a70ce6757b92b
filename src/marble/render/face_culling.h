#pragma once
// Which faces of a mesh the camera's depth test would always discard, so that the geometry pass
// need not draw them (GL face culling); the same for the light, whose depth map and reflective
// shadow map keep the nearest surface too (LightDepthPass; the eye is then the light: a point
// light's perspective, or a directional light's orthographic box, whose eye is at infinity). On llvmpipe a triangle costs its setup and binning and a
// 4x4 block of fragment shading per block it touches, whether or not the depth test keeps any
// fragment: the dragon's 100,000 triangles are half turned away from any eye, and culling them
// took 113 M instructions off the 252.5 M geometry pass of its 800^2 camera frame
// (docs/performance.md, "Twenty-second session: ... s22-cost").
//
// Safe where the first surface along every camera ray is a face turned toward the eye: a closed
// surface (mesh/closed_surface.h) and an eye outside it -- every corner of the mesh's bounding
// box beyond the near plane, so the eye is outside the box and the near plane cuts nothing open
// (through a cut, or a hole, the far side's inner faces are seen). Not exact in two corner cases:
// a pixel whose two nearest fragments have the same depth (mostly on silhouettes, where a facing
// and a turned-away face meet: GL_LESS kept the one drawn first, now the facing one; 4 of the
// dragon's 146,704 pixels at 800^2), and a fold turned inside out, whose region of winding
// number -1 a ray could meet before any outward face (none seen from the reference views' cameras
// on the full meshes; from their lights, the simplified proxies show 2-10 texels of 1024^2, the
// first hit moved by at most 6.6e-4 units, within the proxy's own half-texel error: docs/performance.md,
// "... the light's passes cull ...").
#include <cstddef>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "marble/mesh/closed_surface.h"
#include "marble/render/gpu_mesh.h"

namespace marble {

// GL_BACK or GL_FRONT: the faces no ray from the eye meets first, for the mesh drawn with modelViewProj
// (its winding, its object-space bounding box); GL_NONE where both may be seen. The faces' sense on
// screen follows the sign of modelViewProj's determinant (a projective map's Jacobian is
// det(M) / w^4), so a mirroring model matrix or projection is allowed for.
GLenum facesHiddenFromEye(SurfaceWinding winding, const glm::mat4& modelViewProj, const glm::vec3& boundsMin,
                             const glm::vec3& boundsMax);

// For a mesh pass about to draw `mesh` with modelViewProj: where `enabled` and facesHiddenFromEye
// names a face, turns GL face culling on for it (glFrontFace stays GL's default,
// counter-clockwise); else leaves culling as it is (off, as every pass's state set leaves it). The
// caller turns it off after its draws, since the other passes' state assumes it off.
void cullFacesHiddenFromEye(bool enabled, const GpuMesh& mesh, const glm::mat4& modelViewProj);

// cullFacesHiddenFromEye, and the draws after it without the triangles GL's culling would discard
// for certain (render/screen_cull.h): the same triangles reach the rasterizer in the same order,
// the vertex stage and setup of the others are saved. Reuses its memory from frame to frame.
class HiddenFaceDraw {
public:
  // Turns culling on as cullFacesHiddenFromEye(enabled, ...); where it did and `onCpu`, chooses
  // the triangles to draw for a viewport of width x height pixels (for several viewports, the
  // smallest: its slack in its pixels covers the larger ones' snapping too).
  void prepare(bool enabled, bool onCpu, const GpuMesh& mesh, const glm::mat4& modelViewProj, int width, int height);
  // The mesh, or the triangles prepare chose.
  void draw(const GpuMesh& mesh) const;

private:
  bool subset_ = false;
  size_t keptTriangles_ = 0;  // in the mesh's subset buffer (GpuMesh::mapSubset)
  std::vector<float> scratch_;
};

}  // namespace marble
