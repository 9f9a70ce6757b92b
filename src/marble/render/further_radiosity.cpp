#include "marble/render/further_radiosity.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "marble/core/parallel_for.h"
#include "marble/mesh/mesh_optimize.h"

namespace marble {
namespace {

constexpr float kPi = 3.14159265358979f;
// Rays leave a patch this far off its plane (model units; the object is 2 across): above float's
// rounding at the object's size, far below a patch.
constexpr float kRayOffset = 1e-4f;

// A patch's own turn of the shared ray pattern (Cranley-Patterson rotation), from its index: the
// same numbers on every run and thread count (a hash, not a generator's state).
uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
float unitFloat(uint32_t x) { return static_cast<float>(x >> 8) * (1.0f / 16777216.0f); }
float radicalInverse2(uint32_t k) {
  k = (k << 16) | (k >> 16);
  k = ((k & 0x55555555U) << 1) | ((k & 0xAAAAAAAAU) >> 1);
  k = ((k & 0x33333333U) << 2) | ((k & 0xCCCCCCCCU) >> 2);
  k = ((k & 0x0F0F0F0FU) << 4) | ((k & 0xF0F0F0F0U) >> 4);
  k = ((k & 0x00FF00FFU) << 8) | ((k & 0xFF00FF00U) >> 8);
  return static_cast<float>(k) * (1.0f / 4294967296.0f);
}
float fract(float x) { return x - std::floor(x); }

// Schlick's (1 - cos)^5, the Principled diffuse's F (principled_entry.glsl's weight 1 - F/2).
float schlick5(float c) {
  const float m = 1.0f - std::clamp(c, 0.0f, 1.0f);
  const float m2 = m * m;
  return m2 * m2 * m;
}

// Splits a triangle in four at its edges' midpoints until no edge is longer than kPatchMaxEdge:
// a large flat face (a box's) is one patch otherwise, and its further bounce one value.
template <class Out>
void splitInto(glm::vec3 a, glm::vec3 b, glm::vec3 c, float maxEdge, int depth, Out&& out) {
  const float longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  if (longest <= maxEdge || depth >= 8) {
    out(a, b, c);
    return;
  }
  const glm::vec3 ab = 0.5f * (a + b), bc = 0.5f * (b + c), ca = 0.5f * (c + a);
  splitInto(a, ab, ca, maxEdge, depth + 1, out);
  splitInto(ab, b, bc, maxEdge, depth + 1, out);
  splitInto(ca, bc, c, maxEdge, depth + 1, out);
  splitInto(ab, bc, ca, maxEdge, depth + 1, out);
}

}  // namespace

glm::vec3 FurtherGrid::at(glm::vec3 p) const {
  if (cells < 2) return glm::vec3(0.0f);
  glm::vec4 sum(0.0f);
  int i0[3];
  float f[3];
  for (int a = 0; a < 3; ++a) {
    // GL_LINEAR with CLAMP_TO_EDGE: the texel coordinate less a half, its neighbours clamped.
    const float x = std::clamp((p[a] - lo[a]) / cellSize - 0.5f, 0.0f, static_cast<float>(cells - 1));
    i0[a] = std::min(static_cast<int>(x), cells - 2);
    f[a] = x - static_cast<float>(i0[a]);
  }
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const float w = (dx ? f[0] : 1.0f - f[0]) * (dy ? f[1] : 1.0f - f[1]) * (dz ? f[2] : 1.0f - f[2]);
        sum += w * values[(static_cast<size_t>(i0[2] + dz) * cells + (i0[1] + dy)) * cells + (i0[0] + dx)];
      }
  return sum.w > 0.0f ? glm::vec3(sum) / sum.w : glm::vec3(0.0f);
}

glm::mat4 FurtherGrid::textureFromModel() const {
  const float span = static_cast<float>(cells) * cellSize;
  return glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / span)) * glm::translate(glm::mat4(1.0f), -lo);
}

FurtherRadiosity::~FurtherRadiosity() = default;

FurtherRadiosity::FurtherRadiosity(const Mesh& mesh) {
  const SimplifiedMesh copy = simplifiedMesh(mesh, kPatchTriangles, kPatchMaxErrorUnits);
  const Mesh& m = copy.mesh;
  // The patches face the way the triangles are wound, outward; a mesh wound inward (signed volume
  // below 0) the other way (as the light's layers take it, gpu_mesh.cpp's woundInward). Not the
  // copy's vertex normals: its vertices are welded by position, so a box's corner keeps one face's.
  const float outward = signedVolume(mesh) < 0.0 ? -1.0f : 1.0f;
  Mesh patchMesh;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 a = m.positions[m.indices[t * 3]], b = m.positions[m.indices[t * 3 + 1]], c = m.positions[m.indices[t * 3 + 2]];
    splitInto(a, b, c, kPatchMaxEdge, 0, [&](glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
      const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
      const float len = glm::length(cross);
      if (!(len > 0.0f)) return;  // degenerate: no area, no rays
      patches_.push_back({(p0 + p1 + p2) / 3.0f, outward * cross / len, 0.5f * len});
      const uint32_t base = static_cast<uint32_t>(patchMesh.positions.size());
      patchMesh.positions.insert(patchMesh.positions.end(), {p0, p1, p2});
      patchMesh.indices.insert(patchMesh.indices.end(), {base, base + 1, base + 2});
    });
  }
  const size_t n = patches_.size();
  hitStart_.assign(n + 1, 0);
  if (n == 0) return;
  lo_ = hi_ = patchMesh.positions.front();
  double area = 0.0;
  for (const glm::vec3& p : patchMesh.positions) {
    lo_ = glm::min(lo_, p);
    hi_ = glm::max(hi_, p);
  }
  for (const Patch& p : patches_) area += p.area;
  meanArea_ = static_cast<float>(area / static_cast<double>(n));
  bvh_ = std::make_unique<RayBvh>(patchMesh);
  // Each patch's rays: the hit patches (or n: none, or a patch met from behind), then run-length
  // coded after sorting.
  std::vector<uint32_t> hits(n * kPatchRays);
  parallelFor(n, 256, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const Patch& p = patches_[i];
      const glm::vec3 a = patchMesh.positions[i * 3], b = patchMesh.positions[i * 3 + 1], c = patchMesh.positions[i * 3 + 2];
      const glm::vec3 t = std::abs(p.facing.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
      const glm::vec3 bx = glm::normalize(glm::cross(p.facing, t)), by = glm::cross(p.facing, bx);
      const uint32_t h = hash32(static_cast<uint32_t>(i));
      const float turn1 = unitFloat(h), turn2 = unitFloat(hash32(h)), turn3 = unitFloat(hash32(h + 1)),
                  turn4 = unitFloat(hash32(h + 2));
      for (int k = 0; k < kPatchRays; ++k) {
        // The direction: Hammersley's (k + 0.5) / N and the radical inverse, turned, to a
        // cosine-weighted hemisphere (Malley's method).
        const float u1 = fract((static_cast<float>(k) + 0.5f) / kPatchRays + turn1);
        const float u2 = fract(radicalInverse2(static_cast<uint32_t>(k)) + turn2);
        const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
        const glm::vec3 dir = bx * (r * std::cos(phi)) + by * (r * std::sin(phi)) + p.facing * std::sqrt(std::max(0.0f, 1.0f - u1));
        // The origin over the patch (the same points for every direction would see one point's view).
        const float s1 = fract(static_cast<float>(k) * 0.618034f + turn3);
        const float s2 = fract(static_cast<float>(k) * 0.7548777f + turn4);
        const float su = std::sqrt(s1);
        const glm::vec3 origin = a * (1.0f - su) + b * (su * (1.0f - s2)) + c * (su * s2) + p.facing * kRayOffset;
        const RayHit hit = bvh_->nearest(origin, dir, 1e30f);
        uint32_t j = static_cast<uint32_t>(n);
        if (hit.t > 0.0f && glm::dot(dir, patches_[hit.triangle].facing) < 0.0f) j = hit.triangle;
        hits[i * kPatchRays + k] = j;
      }
    }
  });
  for (size_t i = 0; i < n; ++i) {
    auto first = hits.begin() + static_cast<ptrdiff_t>(i * kPatchRays);
    std::sort(first, first + kPatchRays);
    for (int k = 0; k < kPatchRays;) {
      int e = k;
      while (e < kPatchRays && first[e] == first[k]) ++e;
      if (first[k] < n) {
        hitPatch_.push_back(first[k]);
        hitCount_.push_back(static_cast<uint16_t>(e - k));
      }
      k = e;
    }
    hitStart_[i + 1] = static_cast<uint32_t>(hitPatch_.size());
  }
}

std::vector<float> FurtherRadiosity::directIrradiance(const Light& light, const glm::mat4& model) const {
  const size_t n = patches_.size();
  std::vector<float> direct(n, 0.0f);
  if (n == 0) return direct;
  const glm::mat4 toModel = glm::inverse(model);
  const bool directional = light.type == LightType::Directional;
  const float d0 = glm::length(light.position);
  // For a directional light, the direction toward it; for a point light, its position (model space).
  const glm::vec3 lightModel = directional ? glm::normalize(glm::vec3(toModel * glm::vec4(light.position, 0.0f)))
                                           : glm::vec3(toModel * glm::vec4(light.position, 1.0f));
  const float farAway = 4.0f * glm::length(hi_ - lo_) + 1.0f;
  parallelFor(n, 1024, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const Patch& p = patches_[i];
      glm::vec3 l = directional ? lightModel : lightModel - p.centre;
      const float d = directional ? farAway : glm::length(l);
      if (!(d > 0.0f)) continue;
      if (!directional) l /= d;
      const float cosL = glm::dot(p.facing, l);
      if (cosL <= 0.0f) continue;
      if (bvh_->nearest(p.centre + p.facing * kRayOffset, l, d).t > 0.0f) continue;  // in shadow
      // deferred_common.glsl's light_falloff: PI (d0 / d)^2 at the world-space distance.
      float falloff = kPi;
      if (!directional) {
        const float dw = glm::distance(glm::vec3(model * glm::vec4(p.centre, 1.0f)), light.position);
        falloff = kPi * (d0 / std::max(dw, 1e-4f)) * (d0 / std::max(dw, 1e-4f));
      }
      direct[i] = falloff * cosL * (1.0f - 0.5f * schlick5(cosL));
    }
  });
  return direct;
}

std::vector<std::vector<float>> FurtherRadiosity::bounces(const std::vector<float>& direct) const {
  const size_t n = patches_.size();
  std::vector<std::vector<float>> g;
  const std::vector<float>* from = &direct;
  for (int b = 1; b <= kBounces; ++b) {
    std::vector<float> next(n, 0.0f);
    const std::vector<float>& src = *from;
    for (size_t i = 0; i < n; ++i) {
      float sum = 0.0f;
      for (uint32_t k = hitStart_[i]; k < hitStart_[i + 1]; ++k) sum += static_cast<float>(hitCount_[k]) * src[hitPatch_[k]];
      next[i] = sum * (1.0f / kPatchRays);
    }
    g.push_back(std::move(next));
    from = &g.back();
  }
  return g;
}

std::vector<std::vector<float>> FurtherRadiosity::patchBounces(const Light& light, const glm::mat4& model) const {
  std::vector<std::vector<float>> g = bounces(directIrradiance(light, model));
  for (auto& v : g)
    for (float& x : v) x /= kPi;
  return g;
}

FurtherGrid FurtherRadiosity::solve(const Light& light, const glm::mat4& model) const {
  FurtherGrid grid;
  grid.cells = kGridCells;
  const glm::vec3 centre = 0.5f * (lo_ + hi_);
  const glm::vec3 ext = hi_ - lo_;
  // One cell of margin each side: every patch's trilinear footprint lies inside.
  grid.cellSize = std::max({ext.x, ext.y, ext.z, 1e-6f}) / static_cast<float>(kGridCells - 2);
  grid.lo = centre - 0.5f * static_cast<float>(kGridCells) * grid.cellSize;
  grid.values.assign(static_cast<size_t>(kGridCells) * kGridCells * kGridCells, glm::vec4(0.0f));
  if (patches_.empty()) return grid;
  const std::vector<std::vector<float>> g = bounces(directIrradiance(light, model));
  for (size_t i = 0; i < patches_.size(); ++i) {
    const float w = patches_[i].area / meanArea_;
    const glm::vec4 v(w * g[1][i] / kPi, w * g[2][i] / kPi, w * g[3][i] / kPi, w);
    int i0[3];
    float f[3];
    for (int a = 0; a < 3; ++a) {
      const float x = (patches_[i].centre[a] - grid.lo[a]) / grid.cellSize - 0.5f;
      i0[a] = std::clamp(static_cast<int>(std::floor(x)), 0, kGridCells - 2);
      f[a] = std::clamp(x - static_cast<float>(i0[a]), 0.0f, 1.0f);
    }
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const float t = (dx ? f[0] : 1.0f - f[0]) * (dy ? f[1] : 1.0f - f[1]) * (dz ? f[2] : 1.0f - f[2]);
          grid.values[(static_cast<size_t>(i0[2] + dz) * kGridCells + (i0[1] + dy)) * kGridCells + (i0[0] + dx)] += t * v;
        }
  }
  return grid;
}

}  // namespace marble
