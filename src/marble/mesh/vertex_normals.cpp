// Angle-weighted vertex normals with a crease angle (vertex_normals.h): points by exact position
// (point_ids.h: found once in loadMesh and shared with the duplicate check), smooth edges from
// the triangles around each edge (bucketed by point), fans of corners by union-find, one normal
// per fan, render vertices duplicated where one vertex spans several fans.
#include "marble/mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "marble/core/parallel_for.h"
#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];  // path halving
      x = parent[x];
    }
    return x;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// One use of an edge by a triangle, filed under the edge's lower point id: the higher one, and the
// corner it runs from (3t + k: from corner k to corner (k + 1) % 3) with, in the top bit, whether it
// runs lower -> higher. Corner indices are < 3 * kMaxTriangles < 2^31.
struct EdgeUse {
  uint32_t hi;
  uint32_t fromAndDirection;
  uint32_t from() const { return fromAndDirection & 0x7FFFFFFFu; }
  bool forward() const { return (fromAndDirection >> 31) != 0; }
};

uint32_t nextCorner(uint32_t c) { return c - c % 3 + (c % 3 + 1) % 3; }

}  // namespace

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg) {
  computeVertexNormals(mesh, creaseAngleDeg, pointIds(mesh.positions));
}

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& point) {
  const size_t nv = mesh.positions.size();
  const size_t corners = mesh.indices.size() / 3 * 3;
  if (point.size() != nv) throw std::invalid_argument("computeVertexNormals: one point id per vertex expected");

  // Per triangle: unit normal (zero for degenerate or out-of-range triangles, which take no part);
  // per corner: its angle.
  std::vector<glm::vec3> faceNormal(corners / 3, glm::vec3(0.0f));
  std::vector<float> cornerAngle(corners, 0.0f);
  // Triangles are independent: split over threads (each writes only its own entries).
  parallelFor(corners / 3, 50000, [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; ++t) {
      const uint32_t* v = &mesh.indices[3 * t];
      if (v[0] >= nv || v[1] >= nv || v[2] >= nv) continue;
      if (point[v[0]] == point[v[1]] || point[v[1]] == point[v[2]] || point[v[0]] == point[v[2]]) continue;
      const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[v[0]]), glm::dvec3(mesh.positions[v[1]]),
                               glm::dvec3(mesh.positions[v[2]])};
      const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      const double len = glm::length(n);
      if (!(len > 0.0) || !std::isfinite(len)) continue;
      faceNormal[t] = glm::vec3(n / len);
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
        cornerAngle[3 * t + k] = static_cast<float>(std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2)));
      }
    }
  });
  auto usable = [&](size_t t) { return faceNormal[t] != glm::vec3(0.0f); };

  // Fans: corners of one point joined through smooth edges (or all of them, without a crease).
  UnionFind fans(corners);
  if (creaseAngleDeg >= kNoCreaseDeg) {
    std::vector<uint32_t> firstCorner(nv, kNone);  // by point id (ids are < nv)
    for (uint32_t c = 0; c < corners; ++c) {
      if (!usable(c / 3)) continue;
      uint32_t& first = firstCorner[point[mesh.indices[c]]];
      if (first == kNone) first = c;
      else fans.unite(first, c);
    }
  } else {
    // The uses of each edge side by side: bucketed by lower point (a counting sort, linear), then
    // sorted by higher point within the bucket (a handful each). The same (lo, hi) order as one
    // sort of all uses, and which of an edge's two uses comes first does not change the result
    // (the rule below is symmetric in them).
    // Each corner's point, once (one random read per corner instead of four).
    std::vector<uint32_t> cornerPoint(corners);
    for (uint32_t c = 0; c < corners; ++c) cornerPoint[c] = point[mesh.indices[c]];
    std::vector<uint32_t> bucketStart(nv + 1, 0);
    for (uint32_t c = 0; c < corners; ++c)
      if (usable(c / 3)) ++bucketStart[std::min(cornerPoint[c], cornerPoint[nextCorner(c)]) + 1];
    for (size_t p = 0; p < nv; ++p) bucketStart[p + 1] += bucketStart[p];
    std::vector<EdgeUse> uses(bucketStart[nv]);
    {
      std::vector<uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
      for (uint32_t c = 0; c < corners; ++c) {
        if (!usable(c / 3)) continue;
        const uint32_t a = cornerPoint[c], b = cornerPoint[nextCorner(c)];
        uses[fill[std::min(a, b)]++] = {std::max(a, b), c | (a < b ? 0x80000000u : 0u)};
      }
    }
    const float cosCrease = static_cast<float>(std::cos(creaseAngleDeg * std::numbers::pi / 180.0));
    for (size_t p = 0; p < nv; ++p) {
      EdgeUse* const first = uses.data() + bucketStart[p];
      EdgeUse* const last = uses.data() + bucketStart[p + 1];
      if (first == last) continue;  // (also: no pointer arithmetic on an empty array's null data())
      // Buckets hold ~3 uses: insertion sort, where std::sort's set-up would cost more; a point
      // with very many edges (a fan of thousands of triangles) gets std::sort.
      if (last - first > 16) {
        std::sort(first, last, [](const EdgeUse& x, const EdgeUse& y) { return x.hi < y.hi; });
      } else {
        for (EdgeUse* i = first + 1; i < last; ++i)
          for (EdgeUse* k = i; k > first && k[-1].hi > k->hi; --k) std::swap(k[-1], k[0]);
      }
      for (EdgeUse* i = first; i < last;) {
        EdgeUse* j = i;
        while (j < last && j->hi == i->hi) ++j;
        // Smooth only between exactly two triangles wound the same way (they run the edge in
        // opposite directions) whose normals are within the crease angle: Blender's rule.
        if (j - i == 2 && i[0].forward() != i[1].forward() &&
            glm::dot(faceNormal[i[0].from() / 3], faceNormal[i[1].from() / 3]) >= cosCrease) {
          // Triangle 1 runs the edge A -> B, triangle 2 B -> A: join the corners at the same point.
          const uint32_t a1 = i[0].from(), b1 = nextCorner(a1);
          const uint32_t b2 = i[1].from(), a2 = nextCorner(b2);
          fans.unite(a1, a2);
          fans.unite(b1, b2);
        }
        i = j;
      }
    }
  }

  // One normal per fan: its faces' normals weighted by their corners' angles, added in corner
  // order. The fans numbered in the order of their first corners as they are met: a set's root is
  // its lowest corner, so a corner that is its own root starts a fan, and any other's root was
  // numbered before it. (One compact sum per fan and one root search per corner, instead of a
  // sum per corner -- 57 MB for 1.6 M triangles -- and a second search in the pass below.)
  std::vector<uint32_t> fanOf(corners, kNone);
  std::vector<glm::vec3> fanSum;
  for (uint32_t c = 0; c < corners; ++c) {
    if (!usable(c / 3)) continue;
    const uint32_t root = fans.find(c);
    if (root == c) {
      fanOf[c] = static_cast<uint32_t>(fanSum.size());
      fanSum.emplace_back(0.0f);
    } else {
      fanOf[c] = fanOf[root];
    }
    fanSum[fanOf[c]] += faceNormal[c / 3] * cornerAngle[c];
  }
  { std::vector<uint32_t>().swap(fans.parent); }
  auto unitOr = [](glm::vec3 v, glm::vec3 fallback) {
    const float len = glm::length(v);
    return std::isfinite(len) && len > 0.0f ? v / len : fallback;
  };

  // A render vertex keeps its index for the first fan it meets and is copied for every other one.
  std::vector<uint32_t> vertexFan(nv, kNone);
  std::vector<glm::vec3> normals(nv, glm::vec3(0.0f, 1.0f, 0.0f));
  std::unordered_map<uint64_t, uint32_t> copies;  // (vertex, fan) -> the copy's index
  const bool hasTexcoords = mesh.texcoords.size() == nv;
  for (uint32_t c = 0; c < corners; ++c) {
    if (!usable(c / 3)) continue;
    const uint32_t v = mesh.indices[c], fan = fanOf[c];
    if (vertexFan[v] == kNone) {
      vertexFan[v] = fan;
      normals[v] = unitOr(fanSum[fan], faceNormal[c / 3]);
      continue;
    }
    if (vertexFan[v] == fan) continue;
    const uint64_t key = (static_cast<uint64_t>(v) << 32) | fan;
    auto [it, added] = copies.try_emplace(key, static_cast<uint32_t>(mesh.positions.size()));
    if (added) {
      const glm::vec3 position = mesh.positions[v];  // a copy: push_back may reallocate
      mesh.positions.push_back(position);
      if (hasTexcoords) {
        const glm::vec2 uv = mesh.texcoords[v];
        mesh.texcoords.push_back(uv);
      }
      normals.push_back(unitOr(fanSum[fan], faceNormal[c / 3]));
    }
    mesh.indices[c] = it->second;
  }
  mesh.normals = std::move(normals);
}

}  // namespace marble
