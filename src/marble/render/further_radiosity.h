#pragma once
// The `marble` mode's further diffuse bounces (the second to the fourth) by a radiosity over the
// whole surface, in world space, for the bounce pass's merge (shaders/bounce_merge.glsl), which adds
// them to the first bounce it gathers from the light's map (docs/quality.md, "Twenty-fifth
// session: the further bounces by a world-space radiosity").
//
// Why world space: the further bounces' emitters are mostly surfaces neither the light nor the
// camera sees (the sides and undersides in shadow, the inner faces of folds); a gather over the
// camera's G-buffer found 0.41 of Cycles' further bounces in buddha-side (session 24), and one over
// the light's map 0.15 (session 16). What the references compute is a radiosity: after a diffuse
// bounce Cycles 3.4's Principled BSDF drops its subsurface (svm/closure.h, PATH_RAY_DIFFUSE_ANCESTOR),
// so every surface a bounce ray meets is opaque Principled diffuse, Lambert x albedo x
// (1 - F_L/2)(1 - F_V/2); and Cycles stops a path after 4 diffuse bounces (`diffuse_bounces`, its
// default), so its further bounces are the 2nd, 3rd and 4th.
//
// Once per mesh (the constructor; the renderer passes the light's proxy where there is one): the
// surface as patches, the triangles of a simplified copy
// (kPatchTriangles, moved at most kPatchMaxErrorUnits; triangles with an edge over kPatchMaxEdge
// split in four until none is), and from each patch kPatchRays cosine-weighted rays (Hammersley
// directions, turned per patch; origins spread over the patch) through a BVH of the patches: which
// patch each meets front-on is its form factor's estimate, F_ij = (rays from i meeting j) / rays.
// Per light (solve()): each patch's direct irradiance at its centre, shadowed by a ray, per unit of
// the light's radiance with the stone's entry, E_d = light_falloff x cos x (1 - F_L/2) (the
// convention of marble's direct light); then G_1 = F E_d and G_n = F G_(n-1), albedo-free, so that
// the n-th bounce's irradiance at a receiver is E_n = A^n w^(2n-1) G_n (w = 41/42: the emitters'
// (1 - F/2) averaged over a cosine-weighted hemisphere, on the way in and out), which the merge
// forms with the base colour A, so a base-colour change needs no new solve. G_2..G_4 / PI go onto a
// coarse 3D grid over the object (kGridCells a side), each patch splatted trilinearly at its centre
// with its area as weight; the merge reads it trilinearly and divides by the weight (a normalised
// convolution: the empty cells around the surface drop out).
//
// Approximations (measured in docs/quality.md): the patches' surface stands for the mesh's (the
// simplified copy moves at most kPatchMaxErrorUnits; at 0.16-0.19 units, meshoptimizer's stop on
// the buddha and dragon at 3000 triangles, the gain was lost); one shadow ray per patch; the grid
// blends the two sides of a part thinner than a cell (2.1 / (kGridCells - 2) units; a grid per facing
// that kept them apart lost 0.0005 on buddha-side and gained nothing on dragon-side); the emitters'
// specular layer and retro-reflection are left out (Principled's specular layer does not take from
// the diffuse one in Cycles 3.4, so the diffuse exitance is albedo x w x the irradiance entering).
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "marble/bake/ray_bvh.h"
#include "marble/mesh/mesh.h"
#include "marble/scene/scene.h"

namespace marble {

// The further bounces on a grid over the object, in the mesh's (model) space: cell (i, j, k)'s
// centre is at lo + (i + 0.5, j + 0.5, k + 0.5) x cellSize. Per cell, premultiplied by its weight w
// (the patches' areas splatted there, in units of the mean patch's):
// rgba = (w G_2 / PI, w G_3 / PI, w G_4 / PI, w).
struct FurtherGrid {
  int cells = 0;  // a side
  glm::vec3 lo{0.0f};
  float cellSize = 0.0f;
  std::vector<glm::vec4> values;  // cells^3, x fastest, then y, then z
  // The merge's read (GL_LINEAR over the premultiplied values, then / w): G_2, G_3, G_4 over PI at
  // p, or 0 where no patch reached the cells around it.
  glm::vec3 at(glm::vec3 p) const;
  // Model space to the texture's [0, 1]^3.
  glm::mat4 textureFromModel() const;
};

class FurtherRadiosity {
 public:
  // The mesh as drawn (model space, normals one per position).
  explicit FurtherRadiosity(const Mesh& mesh);
  ~FurtherRadiosity();
  // The light (world space) and the model matrix the frame draws the mesh with.
  FurtherGrid solve(const Light& light, const glm::mat4& model) const;
  size_t patchCount() const { return patches_.size(); }
  // For tests: G_n / PI per patch (n = 1..4, one vector each) of the last solve's light.
  std::vector<std::vector<float>> patchBounces(const Light& light, const glm::mat4& model) const;
  glm::vec3 patchCentre(size_t i) const { return patches_[i].centre; }

  // The patches: ~11 k on the dragon and the buddha after the split (docs/quality.md, "Twenty-fifth
  // session": the ten scenes' mean SSIM the same to 1e-5 as with ~21 k, at half the solve's
  // instructions; a copy moved 0.16-0.19 units lost the gain).
  static constexpr size_t kPatchTriangles = 6000;
  static constexpr float kPatchMaxErrorUnits = 0.02f;
  static constexpr float kPatchMaxEdge = 0.1f;
  static constexpr int kPatchRays = 64;
  // The grid's side: cells of 2.1 / 46 units (the object's largest extent 2.1 over 46 cells and a
  // margin). The read blends the patches over about a cell each side, so the cell is the further
  // bounces' finest detail: with 32 (2.1 / 30 units) the fold test's plate read 0.85-0.94 of its own
  // patches' value 0.07-0.10 from the wall, with 48 0.99-1.02; the ten scenes' mean SSIM +0.0007
  // (buddha-side +0.0017, buddha-back +0.0027, none down more than 0.0003; docs/quality.md,
  // "Twenty-fifth session: ... the radiosity's grid at 48 cells"). 48 and no finer: the read needs a patch centre
  // within its footprint (two cells), and the split leaves patches up to kPatchMaxEdge = 0.1 units
  // across on flat faces (64 cells, footprint 0.066 units, scored +0.0002 more but can leave holes).
  static constexpr int kGridCells = 48;
  static constexpr int kBounces = 4;  // Cycles' diffuse_bounces (its default)

 private:
  struct Patch {
    glm::vec3 centre, facing;  // facing: the outward normal of its plane
    float area;
  };
  std::vector<float> directIrradiance(const Light& light, const glm::mat4& model) const;
  std::vector<std::vector<float>> bounces(const std::vector<float>& direct) const;
  std::vector<Patch> patches_;
  std::unique_ptr<RayBvh> bvh_;  // over the patches, triangle i = patch i
  // The form factors, sparse: patch i's rays met patch hitPatch_[k] hitCount_[k] times, k in
  // [hitStart_[i], hitStart_[i + 1]).
  std::vector<uint32_t> hitStart_, hitPatch_;
  std::vector<uint16_t> hitCount_;
  glm::vec3 lo_{0.0f}, hi_{0.0f};  // the patches' bounds
  float meanArea_ = 1.0f;
};

}  // namespace marble
