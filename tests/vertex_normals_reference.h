#pragma once
// The first implementation of computeVertexNormals (issue 15), kept as the reference the faster
// one must equal bit for bit: points welded by sorting the positions, the edge uses of all
// triangles sorted by (lower point, higher point). Straightforward and n log n; the library's
// version hashes the positions and buckets the edges by point (vertex_normals.cpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "marble/mesh/mesh.h"

namespace marble::reference {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

// Point id per render vertex: vertices at exactly the same position share one (+0 and -0 equal).
inline std::vector<uint32_t> pointIds(const std::vector<glm::vec3>& positions) {
  std::vector<uint32_t> order(positions.size());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](uint32_t a, uint32_t b) {
    const glm::vec3 &p = positions[a], &q = positions[b];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<uint32_t> id(positions.size());
  uint32_t next = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && positions[order[i]] != positions[order[i - 1]]) ++next;
    id[order[i]] = next;
  }
  return id;
}

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

// One use of an edge by a triangle: from corner `from` to the next corner of the same triangle.
struct EdgeUse {
  uint32_t lo, hi;  // point ids, lo < hi
  uint32_t from;    // corner index 3t + k; the edge runs from corner k to corner (k + 1) % 3
  bool forward;     // whether it runs lo -> hi
};

inline uint32_t nextCorner(uint32_t c) { return c - c % 3 + (c % 3 + 1) % 3; }

}  // namespace

inline void computeVertexNormalsBySorting(Mesh& mesh, float creaseAngleDeg) {
  const size_t nv = mesh.positions.size();
  const size_t corners = mesh.indices.size() / 3 * 3;
  const std::vector<uint32_t> point = pointIds(mesh.positions);

  // Per triangle: unit normal (zero for degenerate or out-of-range triangles, which take no part);
  // per corner: its angle.
  std::vector<glm::vec3> faceNormal(corners / 3, glm::vec3(0.0f));
  std::vector<float> cornerAngle(corners, 0.0f);
  for (size_t t = 0; t < corners / 3; ++t) {
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
    std::vector<EdgeUse> uses;
    uses.reserve(corners);
    for (uint32_t c = 0; c < corners; ++c) {
      if (!usable(c / 3)) continue;
      const uint32_t a = point[mesh.indices[c]], b = point[mesh.indices[nextCorner(c)]];
      uses.push_back({std::min(a, b), std::max(a, b), c, a < b});
    }
    std::sort(uses.begin(), uses.end(),
              [](const EdgeUse& x, const EdgeUse& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
    const float cosCrease = static_cast<float>(std::cos(creaseAngleDeg * std::numbers::pi / 180.0));
    for (size_t i = 0; i < uses.size();) {
      size_t j = i;
      while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
      // Smooth only between exactly two triangles wound the same way (they run the edge in
      // opposite directions) whose normals are within the crease angle: Blender's rule.
      if (j - i == 2 && uses[i].forward != uses[i + 1].forward &&
          glm::dot(faceNormal[uses[i].from / 3], faceNormal[uses[i + 1].from / 3]) >= cosCrease) {
        // Triangle 1 runs the edge A -> B, triangle 2 B -> A: join the corners at the same point.
        const uint32_t a1 = uses[i].from, b1 = nextCorner(a1);
        const uint32_t b2 = uses[i + 1].from, a2 = nextCorner(b2);
        fans.unite(a1, a2);
        fans.unite(b1, b2);
      }
      i = j;
    }
  }

  // One normal per fan: its faces' normals weighted by their corners' angles.
  std::vector<glm::vec3> fanSum(corners, glm::vec3(0.0f));
  for (uint32_t c = 0; c < corners; ++c)
    if (usable(c / 3)) fanSum[fans.find(c)] += faceNormal[c / 3] * cornerAngle[c];
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
    const uint32_t v = mesh.indices[c], fan = fans.find(c);
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

}  // namespace marble::reference
