#include "marble/mesh/closed_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

// Union-find over points, for the mesh's connected parts.
uint32_t root(std::vector<uint32_t>& parent, uint32_t p) {
  while (parent[p] != p) p = parent[p] = parent[parent[p]];
  return p;
}

// Whether triangle t's corners are three points (pointIds): one with two corners at a point has
// no area, so no fragment and no crossing, and neither decision counts it.
bool coversArea(const Mesh& mesh, const std::vector<uint32_t>& point, size_t t) {
  const uint32_t* v = &mesh.indices[3 * t];
  const uint32_t a = point[v[0]], b = point[v[1]], c = point[v[2]];
  return a != b && b != c && c != a;
}

// The mesh's connected parts (points joined by the triangles that cover area) and each part's
// signed volume (the divergence theorem, as signedVolume), kept at its root point; other points
// hold 0.
struct Parts {
  std::vector<uint32_t> parent;
  std::vector<double> volume;
};

Parts connectedParts(const Mesh& mesh, const std::vector<uint32_t>& point) {
  const size_t n = mesh.positions.size(), triangles = mesh.triangleCount();
  Parts parts{std::vector<uint32_t>(n), std::vector<double>(n, 0.0)};
  std::iota(parts.parent.begin(), parts.parent.end(), 0u);
  for (size_t t = 0; t < triangles; ++t) {
    if (!coversArea(mesh, point, t)) continue;
    const uint32_t* v = &mesh.indices[3 * t];
    parts.parent[root(parts.parent, point[v[1]])] = root(parts.parent, point[v[0]]);
    parts.parent[root(parts.parent, point[v[2]])] = root(parts.parent, point[v[0]]);
  }
  for (size_t t = 0; t < triangles; ++t) {
    if (!coversArea(mesh, point, t)) continue;
    const uint32_t* v = &mesh.indices[3 * t];
    const glm::dvec3 pa(mesh.positions[v[0]]), pb(mesh.positions[v[1]]), pc(mesh.positions[v[2]]);
    parts.volume[root(parts.parent, point[v[0]])] += glm::dot(pa, glm::cross(pb, pc));
  }
  return parts;
}

}  // namespace

SurfaceWinding closedSurfaceWinding(const Mesh& mesh) {
  const size_t n = mesh.positions.size();
  const size_t triangles = mesh.triangleCount();
  if (triangles == 0) return SurfaceWinding::Open;
  for (uint32_t v : mesh.indices)
    if (v >= n) return SurfaceWinding::Open;
  const std::vector<uint32_t> point = pointIds(mesh.positions);
  // The edges leaving each point, grouped by point (a point has a handful: grouping by counts took
  // half the time of sorting the edges, 10 ms on the dragon's 100,000 triangles).
  std::vector<uint32_t> first(n + 1, 0);
  for (size_t t = 0; t < triangles; ++t) {
    if (!coversArea(mesh, point, t)) continue;
    const uint32_t* v = &mesh.indices[3 * t];
    ++first[point[v[0]] + 1], ++first[point[v[1]] + 1], ++first[point[v[2]] + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<uint32_t> to(3 * triangles), fill(first.begin(), first.end() - 1);
  for (size_t t = 0; t < triangles; ++t) {
    if (!coversArea(mesh, point, t)) continue;
    const uint32_t* v = &mesh.indices[3 * t];
    const uint32_t a = point[v[0]], b = point[v[1]], c = point[v[2]];
    to[fill[a]++] = b, to[fill[b]++] = c, to[fill[c]++] = a;
  }
  // Each edge used as often one way as the other (a surface without boundary: its triangles'
  // windings cancel along every edge). Two triangles an edge, wound against each other, is the
  // common case; simplified copies also have edges of four where two parts touch (the dragon's
  // light proxy: 98 of them), which leave the winding number as defined.
  const auto uses = [&](uint32_t from, uint32_t target) {
    return std::count(to.begin() + first[from], to.begin() + first[from + 1], target);
  };
  for (uint32_t a = 0; a < n; ++a)
    for (uint32_t i = first[a]; i < first[a + 1]; ++i)
      if (uses(a, to[i]) != uses(to[i], a)) return SurfaceWinding::Open;
  Parts parts = connectedParts(mesh, point);
  bool anyPositive = false, anyNegative = false, anyZero = false;
  for (uint32_t p = 0; p < n; ++p) {
    if (first[p] == first[p + 1] || root(parts.parent, p) != p) continue;  // no edge leaves it, or not a part's root
    anyPositive |= parts.volume[p] > 0.0;
    anyNegative |= parts.volume[p] < 0.0;
    anyZero |= parts.volume[p] == 0.0;
  }
  if (anyZero || (anyPositive && anyNegative)) return SurfaceWinding::Open;
  return anyPositive ? SurfaceWinding::Outward : SurfaceWinding::Inward;
}

size_t orientSlivers(Mesh& mesh) {
  const size_t n = mesh.positions.size();
  const size_t triangles = mesh.triangleCount();
  for (uint32_t v : mesh.indices)
    if (v >= n) return 0;
  const std::vector<uint32_t> point = pointIds(mesh.positions);
  Parts parts = connectedParts(mesh, point);
  const std::vector<double>& volume = parts.volume;
  double largest = 0.0;
  for (double v : volume)
    if (std::abs(v) > std::abs(largest)) largest = v;
  std::vector<char> turn(n, 0);
  size_t turned = 0;
  for (uint32_t p = 0; p < n; ++p) {
    if (volume[p] * largest < 0.0 && std::abs(volume[p]) <= kSliverVolumeFraction * std::abs(largest)) {
      turn[p] = 1;
      ++turned;
    }
  }
  if (turned == 0) return 0;
  for (size_t t = 0; t < triangles; ++t)
    if (coversArea(mesh, point, t) && turn[root(parts.parent, point[mesh.indices[3 * t]])])
      std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
  return turned;
}

}  // namespace marble
