#pragma once
// The triangles GL's face culling would discard, dropped on the CPU before the draw, so that
// llvmpipe does not shade their vertices and set them up only to cull them (the dragon's camera
// frame: 53,000 of 100,000 triangles; docs/performance.md, "Twenty-eighth session: ... s28-cost").
// Exact by construction: GL culling stays on, and a triangle is dropped only where every
// position GL could compute for its corners gives it the culled sense or no area, so GL draws the
// same triangles in the same order and the pictures do not change by a bit.
//
// The margin: llvmpipe decides a triangle's sense on its corners' window positions snapped to
// 1/256 pixel (lp_setup_tri.c, FIXED_ORDER 8: at most 1/512 pixel moved), and its vertex shader
// computes them in single precision in another order than this code (modelViewProj here, view_proj
// times model there: a few 1e-4 pixel apart at 800^2). kScreenCullSlackPixels (1/128 pixel, twice
// both together) bounds how far each window coordinate may be from the one computed here; a
// triangle is dropped only if its doubled signed area stays of the culled sense under any such move
// of its corners (the area's change is at most 2 slack (|ax| + |ay| + |bx| + |by|) + 8 slack^2 for
// edges a, b from the first corner). Corners outside the view volume (GL clips such triangles into
// new ones, whose sense this code does not follow) keep their triangle.
//
// The cost: a projection per vertex and the sign of each triangle's plane against the eye (both
// vectorized over separate arrays of coordinates); a triangle that faces the eye is kept at once
// (keeping needs no margin), the rest go through the test above: 4.3 M instructions of the
// dragon's 800^2 camera frame (100,000 triangles, 50,000 vertices) against 11.7 M saved in GL.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"

namespace marble {

inline constexpr double kScreenCullSlackPixels = 1.0 / 128.0;

enum class CulledSense {
  Clockwise,         // glCullFace(GL_BACK) with glFrontFace(GL_CCW): drawn only counter-clockwise on screen
  CounterClockwise,  // glCullFace(GL_FRONT)
};

// What the cull reads of a mesh, made once per mesh: the positions' coordinates each in its own
// array, the indices, and per triangle the four 3 x 3 minors of its corners' homogeneous
// coordinates (x, y, z, 1) without one column each (the plane's coefficients: the sign of their
// product with the view's minors is the triangle's sense on screen, Cauchy-Binet).
struct ScreenCullMesh {
  ScreenCullMesh() = default;
  explicit ScreenCullMesh(const Mesh& mesh);
  std::vector<float> x, y, z;
  std::vector<uint32_t> indices;
  std::vector<float> planeX, planeY, planeZ, planeW;  // per triangle
};

// Writes to kept[0, 3 n) the n triangles of mesh.indices (three a triangle, in their order) that
// GL, drawing the mesh with modelViewProj into a viewport of width x height pixels with the
// `culled` faces culled, might draw, and returns n; `kept` has room for mesh.indices.size() (it
// is only written: a mapped buffer will do). `scratch` is reused memory.
size_t trianglesGlMayDraw(const ScreenCullMesh& mesh, const glm::mat4& modelViewProj, int width, int height,
                          CulledSense culled, uint32_t* kept, std::vector<float>& scratch,
                          double slackPixels = kScreenCullSlackPixels);

}  // namespace marble
