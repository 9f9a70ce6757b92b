#include "marble/mesh/closed_surface.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

uint64_t edgeKey(uint32_t from, uint32_t to) { return static_cast<uint64_t>(from) << 32 | to; }

// Union-find over points, for the mesh's connected parts.
uint32_t root(std::vector<uint32_t>& parent, uint32_t p) {
  while (parent[p] != p) p = parent[p] = parent[parent[p]];
  return p;
}

}  // namespace

SurfaceWinding closedSurfaceWinding(const Mesh& mesh) {
  const size_t n = mesh.positions.size();
  const size_t triangles = mesh.triangleCount();
  if (triangles == 0) return SurfaceWinding::Open;
  const std::vector<uint32_t> point = pointIds(mesh.positions);
  std::vector<uint64_t> edges;
  edges.reserve(3 * triangles);
  std::vector<uint32_t> parent(n);
  std::vector<char> used(n, 0);  // points a triangle has (a vertex of none is no part)
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    if (v[0] >= n || v[1] >= n || v[2] >= n) return SurfaceWinding::Open;
    const uint32_t a = point[v[0]], b = point[v[1]], c = point[v[2]];
    if (a == b || b == c || c == a) return SurfaceWinding::Open;
    edges.insert(edges.end(), {edgeKey(a, b), edgeKey(b, c), edgeKey(c, a)});
    used[a] = used[b] = used[c] = 1;
    parent[root(parent, b)] = root(parent, a);
    parent[root(parent, c)] = root(parent, a);
  }
  // Each directed edge once, and its reverse once: two triangles per edge, wound against each other.
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return SurfaceWinding::Open;
  for (uint64_t e : edges)
    if (!std::binary_search(edges.begin(), edges.end(), e << 32 | e >> 32)) return SurfaceWinding::Open;
  // Each part's signed volume (the divergence theorem, as signedVolume), summed at its root point.
  std::vector<double> volume(n, 0.0);
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    const glm::dvec3 pa(mesh.positions[v[0]]), pb(mesh.positions[v[1]]), pc(mesh.positions[v[2]]);
    volume[root(parent, point[v[0]])] += glm::dot(pa, glm::cross(pb, pc));
  }
  bool anyPositive = false, anyNegative = false, anyZero = false;
  for (uint32_t p = 0; p < n; ++p) {
    if (!used[p] || root(parent, p) != p) continue;  // not a part's root
    anyPositive |= volume[p] > 0.0;
    anyNegative |= volume[p] < 0.0;
    anyZero |= volume[p] == 0.0;
  }
  if (anyZero || (anyPositive && anyNegative)) return SurfaceWinding::Open;
  return anyPositive ? SurfaceWinding::Outward : SurfaceWinding::Inward;
}

}  // namespace marble
