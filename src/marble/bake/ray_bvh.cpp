#include "marble/bake/ray_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace marble {

namespace {
constexpr uint32_t kLeafSize = 4;
constexpr int kBins = 16;

float halfArea(glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 e = hi - lo;
  return e.x * e.y + e.y * e.z + e.z * e.x;
}
}  // namespace

// Where to split [begin, end) along `axis`: the surface area heuristic (a ray's chance of
// entering a box is proportional to its area, so the split minimizing area x triangles on both
// sides minimizes the expected work), evaluated over kBins equal bins of the centroids' extent
// (Wald, "On fast construction of SAH-based bounding volume hierarchies", 2007). Returns how
// many triangles, counted from begin, go left, as an index: the caller orders the triangles by
// centroid so that exactly those come first. A degenerate extent, or a best split that leaves
// one side empty, falls back to the median.
uint32_t RayBvh::splitPoint(uint32_t begin, uint32_t end, int axis, float lo, float extent, const std::vector<glm::vec3>& centroids) const {
  const uint32_t median = begin + (end - begin) / 2;
  if (!(extent > 0.0f)) return median;
  struct Bin {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
    uint32_t count = 0;
  };
  Bin bins[kBins];
  const float scale = kBins / extent;
  for (uint32_t t = begin; t < end; ++t) {
    const int b = std::min(kBins - 1, static_cast<int>((centroids[t][axis] - lo) * scale));
    for (int k = 0; k < 3; ++k) {
      bins[b].lo = glm::min(bins[b].lo, corners_[t * 3 + k]);
      bins[b].hi = glm::max(bins[b].hi, corners_[t * 3 + k]);
    }
    ++bins[b].count;
  }
  // Cost of splitting after bin i: areas and counts of both sides, by a sweep from each end.
  float rightArea[kBins];
  uint32_t rightCount[kBins];
  glm::vec3 rlo(std::numeric_limits<float>::max()), rhi(std::numeric_limits<float>::lowest());
  uint32_t rc = 0;
  for (int i = kBins - 1; i > 0; --i) {
    rlo = glm::min(rlo, bins[i].lo);
    rhi = glm::max(rhi, bins[i].hi);
    rc += bins[i].count;
    rightArea[i] = rc > 0 ? halfArea(rlo, rhi) : 0.0f;
    rightCount[i] = rc;
  }
  glm::vec3 llo(std::numeric_limits<float>::max()), lhi(std::numeric_limits<float>::lowest());
  uint32_t lc = 0, bestLeft = 0;
  float bestCost = std::numeric_limits<float>::max();
  for (int i = 0; i < kBins - 1; ++i) {
    llo = glm::min(llo, bins[i].lo);
    lhi = glm::max(lhi, bins[i].hi);
    lc += bins[i].count;
    if (lc == 0 || rightCount[i + 1] == 0) continue;
    const float cost = halfArea(llo, lhi) * static_cast<float>(lc) + rightArea[i + 1] * static_cast<float>(rightCount[i + 1]);
    if (cost < bestCost) {
      bestCost = cost;
      bestLeft = lc;
    }
  }
  return bestLeft == 0 ? median : begin + bestLeft;
}

RayBvh::RayBvh(const Mesh& mesh) {
  const uint32_t n = static_cast<uint32_t>(mesh.triangleCount());
  corners_.resize(static_cast<size_t>(n) * 3);
  triangles_.resize(n);
  std::iota(triangles_.begin(), triangles_.end(), 0u);
  std::vector<glm::vec3> centroids(n);
  for (uint32_t t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k) corners_[t * 3 + k] = mesh.positions[mesh.indices[t * 3 + k]];
    centroids[t] = (corners_[t * 3] + corners_[t * 3 + 1] + corners_[t * 3 + 2]) / 3.0f;
  }
  nodes_.reserve(2 * (n / kLeafSize + 1));
  if (n > 0) build(0, n, centroids);
}

// Sorts triangles [begin, end) in place (corners_ and centroids together) and appends nodes.
uint32_t RayBvh::build(uint32_t begin, uint32_t end, std::vector<glm::vec3>& centroids) {
  const uint32_t id = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back({});
  Node node{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest()), begin, end - begin, 0};
  glm::vec3 clo = node.lo, chi = node.hi;
  for (uint32_t t = begin; t < end; ++t) {
    for (int k = 0; k < 3; ++k) {
      node.lo = glm::min(node.lo, corners_[t * 3 + k]);
      node.hi = glm::max(node.hi, corners_[t * 3 + k]);
    }
    clo = glm::min(clo, centroids[t]);
    chi = glm::max(chi, centroids[t]);
  }
  if (end - begin > kLeafSize) {
    const glm::vec3 ext = chi - clo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    const uint32_t mid = splitPoint(begin, end, axis, clo[axis], ext[axis], centroids);
    std::vector<uint32_t> idx(end - begin);
    std::iota(idx.begin(), idx.end(), begin);
    std::nth_element(idx.begin(), idx.begin() + (mid - begin), idx.end(),
                     [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    std::vector<glm::vec3> c(idx.size() * 3), cen(idx.size());
    std::vector<uint32_t> tri(idx.size());
    for (size_t i = 0; i < idx.size(); ++i) {
      for (int k = 0; k < 3; ++k) c[i * 3 + k] = corners_[idx[i] * 3 + k];
      cen[i] = centroids[idx[i]];
      tri[i] = triangles_[idx[i]];
    }
    std::copy(c.begin(), c.end(), corners_.begin() + static_cast<ptrdiff_t>(begin) * 3);
    std::copy(cen.begin(), cen.end(), centroids.begin() + begin);
    std::copy(tri.begin(), tri.end(), triangles_.begin() + begin);
    node.count = 0;
    node.first = build(begin, mid, centroids);
    node.right = build(mid, end, centroids);
  }
  nodes_[id] = node;
  return id;
}

RayHit RayBvh::nearest(glm::vec3 origin, glm::vec3 dir, float maxT) const {
  RayHit result;
  if (nodes_.empty()) return result;
  const glm::vec3 inv(1.0f / dir.x, 1.0f / dir.y, 1.0f / dir.z);
  float best = maxT;
  bool hit = false;
  uint32_t bestSlot = 0;
  float bestU = 0.0f, bestV = 0.0f;
  // Entry distance of a ray into a node's box, or +inf when it misses or enters beyond `best`.
  auto entry = [&](const Node& node) {
    const glm::vec3 t0 = (node.lo - origin) * inv, t1 = (node.hi - origin) * inv;
    const glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
    const float enter = std::max({tn.x, tn.y, tn.z, 0.0f}), leave = std::min({tf.x, tf.y, tf.z, best});
    return enter <= leave ? enter : std::numeric_limits<float>::infinity();
  };
  struct Pending {
    uint32_t node;
    float enter;
  };
  Pending stack[64];
  int top = 0;
  if (entry(nodes_[0]) < std::numeric_limits<float>::infinity()) stack[top++] = {0, 0.0f};
  while (top > 0) {
    const Pending item = stack[--top];
    if (item.enter > best) continue;  // a nearer hit was found since it was pushed
    const Node& node = nodes_[item.node];
    if (node.count == 0) {
      // Nearer child last, so it is visited first and its hits prune the other.
      const float l = entry(nodes_[node.first]), r = entry(nodes_[node.right]);
      const bool leftFirst = l <= r;
      const Pending nearer{leftFirst ? node.first : node.right, leftFirst ? l : r};
      const Pending farther{leftFirst ? node.right : node.first, leftFirst ? r : l};
      if (farther.enter < std::numeric_limits<float>::infinity()) stack[top++] = farther;
      if (nearer.enter < std::numeric_limits<float>::infinity()) stack[top++] = nearer;
      continue;
    }
    for (uint32_t t = node.first; t < node.first + node.count; ++t) {
      const glm::vec3 a = corners_[t * 3], e1 = corners_[t * 3 + 1] - a, e2 = corners_[t * 3 + 2] - a;
      const glm::vec3 p = glm::cross(dir, e2);
      const float det = glm::dot(e1, p);
      if (std::abs(det) < 1e-12f) continue;
      const float invDet = 1.0f / det;
      const glm::vec3 s = origin - a;
      const float u = glm::dot(s, p) * invDet;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 q = glm::cross(s, e1);
      const float v = glm::dot(dir, q) * invDet;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float d = glm::dot(e2, q) * invDet;
      if (d > 0.0f && d < best) {
        best = d;
        hit = true;
        bestSlot = t;
        bestU = u;
        bestV = v;
      }
    }
  }
  if (hit) result = {best, triangles_[bestSlot], bestU, bestV};
  return result;
}

}  // namespace marble
