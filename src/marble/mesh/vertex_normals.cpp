// Angle-weighted vertex normals with a crease angle (vertex_normals.h): points by exact position
// (point_ids.h), each triangle's normal and angles computed as its corners are filed under their
// points (a counting sort), then point by point the smooth edges, the fans of corners, one normal
// per fan and the render vertices duplicated where one vertex spans several fans; both passes
// over threads. Bit for bit the result of the sort-based reference
// (tests/vertex_normals_reference.h): the same fans, each fan's sum added in corner order, the
// copies numbered in the order of their first corners.
#include "marble/mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "marble/core/parallel_for.h"
#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

// A corner as its point's fan pass sees it (filed under its point by a counting sort, in corner
// order): the corner, its render vertex, the points of the triangle's other two corners, the
// triangle's normal (zero: the triangle takes no part) and the corner's angle. (Carried in the
// record so that the pass reads one list per point: gathering the normals from per-triangle
// arrays instead cost cache misses that were most of the pass's time.)
struct PointCorner {
  uint32_t corner;
  uint32_t vertex;
  uint32_t next;  // the point of the next corner (the triangle's edge leaving this point goes there)
  uint32_t prev;  // the point of the previous corner (the edge arriving here comes from there)
  glm::vec3 faceNormal;
  float angle;
};

// One end of an edge at a point: the edge's other point, the corner (index into the point's list)
// and whether the edge leaves the point there (the triangle runs point -> other) or arrives.
struct EdgeEnd {
  uint32_t other;
  uint32_t cornerAndLeaves;  // list index << 1 | leaves
};

// Union-find over one point's corners (list indices); the root of a set is its lowest index, i.e.
// its first corner in file order -- the fan's corner the global union-find of the reference
// (tests/vertex_normals_reference.h) also took as the root.
void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  a = find(a);
  b = find(b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

// A copy of a render vertex for a fan other than the first it met: made at the corner `first`
// (the pair's first corner in file order), numbered in that order after the pass.
struct Copy {
  uint32_t first;
  uint32_t vertex;
  glm::vec3 normal;
};

// Marks, in mesh.indices during the fan pass, a corner whose vertex is a copy: the copy's first
// corner in the low bits (corners and vertex indices are < 2^31: kMaxTriangles, kMaxVertices).
constexpr uint32_t kCopyMark = 0x80000000u;

}  // namespace

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg) {
  computeVertexNormals(mesh, creaseAngleDeg, pointIds(mesh.positions));
}

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& point) {
  const size_t nv = mesh.positions.size();
  const size_t corners = mesh.indices.size() / 3 * 3;
  if (point.size() != nv) throw std::invalid_argument("computeVertexNormals: one point id per vertex expected");

  const size_t triangles = corners / 3;
  const bool crease = creaseAngleDeg < kNoCreaseDeg;
  const float cosCrease = static_cast<float>(std::cos(creaseAngleDeg * std::numbers::pi / 180.0));
  // A triangle takes part when its indices are in range, its three points differ and its normal
  // is finite and not zero; the first two are checked here, the normal when it is made.
  auto trianglePoints = [&](size_t t, uint32_t q[3]) {
    const uint32_t* v = &mesh.indices[3 * t];
    if (v[0] >= nv || v[1] >= nv || v[2] >= nv) return false;
    for (int k = 0; k < 3; ++k) q[k] = point[v[k]];
    return q[0] != q[1] && q[1] != q[2] && q[0] != q[2];
  };

  // The corners filed under their points, in corner order within each point (a stable counting
  // sort), each with its triangle's other two points, normal and its angle: every edge at a point
  // is seen from the point's own corners, so fans are found point by point with no table over
  // all edges. Over threads: the triangles split in parts, each part counted into its own array,
  // the counts turned into each part's places (part 0's corners at a point before part 1's: still
  // corner order), then each part's triangles measured and filed.
  const unsigned parts = workerThreadCount(triangles, 50000, 4);
  auto partBegin = [&](size_t i) { return triangles * i / parts; };
  std::vector<std::vector<uint32_t>> fill(parts);  // [part][point]: a count, then the next place
  parallelFor(parts, 1, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      fill[i].assign(nv, 0);
      uint32_t q[3];
      for (size_t t = partBegin(i); t < partBegin(i + 1); ++t)
        if (trianglePoints(t, q))
          for (int k = 0; k < 3; ++k) ++fill[i][q[k]];
    }
  });
  std::vector<uint32_t> pointStart(nv + 1);
  uint32_t filed = 0;
  for (size_t p = 0; p < nv; ++p) {
    pointStart[p] = filed;
    for (unsigned i = 0; i < parts; ++i) filed += std::exchange(fill[i][p], filed);
  }
  pointStart[nv] = filed;
  // (Not zeroed first: every element is written below. Transparent huge pages were tried for
  // this scattered fill: faster on a process's later loads, slower on its first, where the kernel
  // compacts memory to find them.)
  std::unique_ptr<PointCorner[]> byPointStore(new PointCorner[filed]);
  PointCorner* const byPointData = byPointStore.get();
  std::vector<uint8_t> usableTriangle(triangles, 0);
  parallelFor(parts, 1, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      uint32_t q[3];
      for (size_t t = partBegin(i); t < partBegin(i + 1); ++t) {
        if (!trianglePoints(t, q)) continue;
        // The unit normal in double (zero: the triangle takes no part), each corner's angle.
        const uint32_t* v = &mesh.indices[3 * t];
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[v[0]]), glm::dvec3(mesh.positions[v[1]]),
                                 glm::dvec3(mesh.positions[v[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double len = glm::length(n);
        glm::vec3 faceNormal(0.0f);
        float angle[3] = {0.0f, 0.0f, 0.0f};
        if (len > 0.0 && std::isfinite(len)) {
          faceNormal = glm::vec3(n / len);
          usableTriangle[t] = faceNormal != glm::vec3(0.0f);
          for (int k = 0; k < 3; ++k) {
            const glm::dvec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
            angle[k] = static_cast<float>(std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2)));
          }
        }
        for (uint32_t k = 0; k < 3; ++k)
          byPointData[fill[i][q[k]]++] = {static_cast<uint32_t>(3 * t + k), v[k], q[(k + 1) % 3], q[(k + 2) % 3],
                                          faceNormal, angle[k]};
      }
    }
  });
  { std::vector<std::vector<uint32_t>>().swap(fill); }

  auto unitOr = [](glm::vec3 v, glm::vec3 fallback) {
    const float len = glm::length(v);
    return std::isfinite(len) && len > 0.0f ? v / len : fallback;
  };
  // Per render vertex, the first fan it met (by the fan's first corner): it keeps its index for
  // that fan; every other fan of the vertex gets a copy.
  std::vector<uint32_t> vertexFan(nv, kNone);
  std::vector<glm::vec3> normals(nv, glm::vec3(0.0f, 1.0f, 0.0f));
  std::vector<Copy> copies;
  std::mutex copiesMutex;

  // Point by point (independent: a render vertex, and each corner, belongs to one point; so
  // over threads): the point's fans, their normals, the vertices' fans.
  parallelFor(nv, 20000, [&](size_t pointBegin, size_t pointEnd) {
    std::vector<uint32_t> root;
    std::vector<EdgeEnd> ends;
    std::vector<glm::vec3> sum;
    std::vector<Copy> found;
    std::unordered_map<uint64_t, uint32_t> pairFirst;  // (vertex, fan root) -> first corner, rare
    for (size_t p = pointBegin; p < pointEnd; ++p) {
      const PointCorner* const list = byPointData + pointStart[p];
      const uint32_t m = pointStart[p + 1] - pointStart[p];
      if (m == 0) continue;
      // A corner of a triangle without a normal (zero area: a degenerate one) takes no part.
      auto takesPart = [&](uint32_t i) { return list[i].faceNormal != glm::vec3(0.0f); };
      root.resize(m);
      if (!crease) {
        // One fan: every corner of the point, its first the first that takes part.
        uint32_t first = 0;
        while (first < m && !takesPart(first)) ++first;
        if (first == m) continue;
        std::fill(root.begin(), root.end(), first);
      } else {
        std::iota(root.begin(), root.end(), 0u);
        // Each edge at the point, with the corners that use it: an edge leaves the point at a
        // corner whose next point is the other end, and arrives at one whose previous point is.
        // (Every usable triangle on the edge has exactly one corner here, so these are all its
        // uses.) Sorted by the other end: insertion sort for the usual handful, std::sort for a
        // point with very many edges.
        ends.clear();
        for (uint32_t i = 0; i < m; ++i) {
          if (!takesPart(i)) continue;
          ends.push_back({list[i].next, i << 1 | 1u});
          ends.push_back({list[i].prev, i << 1});
        }
        if (ends.size() > 32) {
          std::sort(ends.begin(), ends.end(), [](const EdgeEnd& x, const EdgeEnd& y) { return x.other < y.other; });
        } else {
          for (size_t i = 1; i < ends.size(); ++i)
            for (size_t k = i; k > 0 && ends[k - 1].other > ends[k].other; --k) std::swap(ends[k - 1], ends[k]);
        }
        for (size_t i = 0; i < ends.size();) {
          size_t j = i;
          while (j < ends.size() && ends[j].other == ends[i].other) ++j;
          // Smooth only between exactly two triangles wound the same way (one leaves the point
          // along the edge, the other arrives) whose normals are within the crease angle:
          // Blender's rule. (dot is symmetric, so the order of the two does not matter.)
          if (j - i == 2 && ((ends[i].cornerAndLeaves ^ ends[i + 1].cornerAndLeaves) & 1u)) {
            const uint32_t a = ends[i].cornerAndLeaves >> 1, b = ends[i + 1].cornerAndLeaves >> 1;
            if (glm::dot(list[a].faceNormal, list[b].faceNormal) >= cosCrease)
              unite(root, a, b);
          }
          i = j;
        }
        // Every set's root is its lowest index, so in index order each parent is final already.
        for (uint32_t i = 0; i < m; ++i) root[i] = root[root[i]];
      }
      // One normal per fan: its faces' normals weighted by their corners' angles, added in corner
      // order (the reference's order, so the same float sums).
      sum.assign(m, glm::vec3(0.0f));
      for (uint32_t i = 0; i < m; ++i)
        if (takesPart(i)) sum[root[i]] += list[i].faceNormal * list[i].angle;
      bool pairsUsed = false;
      for (uint32_t i = 0; i < m; ++i) {
        if (!takesPart(i)) continue;
        const uint32_t c = list[i].corner, v = list[i].vertex, r = root[i], fan = list[r].corner;
        if (vertexFan[v] == kNone) {
          vertexFan[v] = fan;
          normals[v] = unitOr(sum[r], list[i].faceNormal);
          continue;
        }
        if (vertexFan[v] == fan) continue;
        // A copy of v for this fan: the pair's first corner is the fan's first when that corner
        // has the same vertex; otherwise (a texture seam inside a smooth fan) looked up.
        uint32_t first = fan;
        if (list[r].vertex != v) {
          pairsUsed = true;
          first = pairFirst.try_emplace((static_cast<uint64_t>(v) << 32) | fan, c).first->second;
        }
        if (first == c) found.push_back({c, v, unitOr(sum[r], list[i].faceNormal)});
        mesh.indices[c] = kCopyMark | first;
      }
      if (pairsUsed) pairFirst.clear();
    }
    const std::lock_guard<std::mutex> lock(copiesMutex);
    copies.insert(copies.end(), found.begin(), found.end());
  });
  byPointStore.reset();

  // The copies numbered in the order of their first corners (the reference's order): each marked
  // corner takes its pair's index, which the pair's first corner (earlier) received.
  std::sort(copies.begin(), copies.end(), [](const Copy& a, const Copy& b) { return a.first < b.first; });
  const bool hasTexcoords = mesh.texcoords.size() == nv;
  mesh.positions.reserve(nv + copies.size());
  if (hasTexcoords) mesh.texcoords.reserve(nv + copies.size());
  normals.reserve(nv + copies.size());
  size_t next = 0;
  for (uint32_t c = 0; c < corners; ++c) {
    const uint32_t x = mesh.indices[c];
    if (!(x & kCopyMark) || !usableTriangle[c / 3]) continue;  // (an index out of range is no mark)
    const uint32_t first = x & ~kCopyMark;
    if (first != c) {
      mesh.indices[c] = mesh.indices[first];
      continue;
    }
    const Copy& copy = copies[next++];
    mesh.indices[c] = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(mesh.positions[copy.vertex]);  // (capacity reserved: no reallocation)
    if (hasTexcoords) mesh.texcoords.push_back(mesh.texcoords[copy.vertex]);
    normals.push_back(copy.normal);
  }
  mesh.normals = std::move(normals);
}

}  // namespace marble
