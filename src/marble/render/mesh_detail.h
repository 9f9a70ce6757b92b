#pragma once
// When the renderer draws simplified copies of its mesh (mesh/mesh_optimize.h), and how far
// they may depart from it. Every figure here is measured in docs/performance.md and bounded by
// tests/mesh_detail_gl_test.cpp.
#include <cstddef>

#include "marble/render/view_setup.h"

namespace marble {

// The light's pass (light depth: thickness and shadows) draws a proxy above this many
// triangles. The light's map is 1024² over the bounding sphere: a surface that moves by less
// than half of one of its texels moves the map's samples by no more than the map's own
// rounding, so the proxy keeps every collapse under that. It aims at a quarter of the
// triangles, at most kLightProxyMaxTriangles (what the light's pass draws in the time of the
// 100 k dragon's); on detailed meshes the error cap binds first (the dragon: 29,652 triangles).
// The light's maps at interaction detail (Renderer::setLightMapDetail, 512² at the resolution
// scale 0.5) draw a copy of the proxy under the same rule at their size -- half of their texel,
// aiming at the proxy's triangles times the share of texels -- (the dragon: 10,290 triangles).
constexpr size_t kLightProxyMinTriangles = 60000;
constexpr double kLightProxyTriangleFraction = 0.25;
constexpr size_t kLightProxyMaxTriangles = 100000;
constexpr float lightProxyMaxErrorUnits(int lightMapSize) {
  return 0.5f * (2.0f * kBoundingRadius) / static_cast<float>(lightMapSize);
}

// Interaction detail (the viewer, `marble bench --interaction-detail`): while the view moves,
// the camera's passes draw a copy of at most about this many triangles -- what this machine
// draws interactively (the 100 k dragon: ≈ 40 ms a camera frame on llvmpipe) -- with no
// collapse moving the surface by more than 0.25 % of the normalized mesh's size of 2 (≈ 1 pixel
// when the mesh fills 800 pixels). Where the light's proxy has no more triangles than that, the
// proxy is the copy (within half a light texel, 0.0017 units: the dragon draws 29,652 triangles
// while it moves); otherwise the copy is simplified from the proxy (a few times cheaper than
// from the full mesh; the two bounds then add up: ≤ 0.0067 units). The viewer turns it on by
// default above kInteractionMinTriangles: wherever there is a proxy (session 9; it was 250,000).
constexpr size_t kInteractionTriangles = 100000;
constexpr float kInteractionMaxErrorUnits = 0.005f;
constexpr size_t kInteractionMinTriangles = kLightProxyMinTriangles;

// Dynamic resolution while the view or the light moves (the viewer's `--interaction-resolution`,
// Renderer::setResolutionScale): half the width and height, a quarter of the pixels, for every
// mesh (the screen passes cost by the pixel, not by the triangle). docs/performance.md, "Ninth
// session", measures what it saves and what a moving frame loses; 1 turns it off.
constexpr float kDefaultInteractionResolution = 0.5f;

}  // namespace marble
