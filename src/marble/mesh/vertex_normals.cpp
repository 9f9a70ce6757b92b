// Angle-weighted vertex normals with a crease angle (vertex_normals.h), point by point: points by
// exact position (point_ids.h: found once in loadMesh and shared with the duplicate check); the
// usable corners filed under their points (a counting sort, stable: each point's list is in corner
// order); then each point alone -- over threads, no locks -- finds its edges among its own corners'
// neighbours, joins its corners into fans, sums each fan's normal and settles its vertices. Only
// the copies of vertices that span several fans are numbered on one thread, afterwards. In
// loadMesh the same pass also finds the duplicate triangles, point by point (settlePoint), so the
// separate hash-table check (duplicate_triangles.h) is not needed there.
//
// Why per point: a set of corners joined through smooth edges never crosses points (two corners
// are joined only at a shared point), and every triangle that uses an edge {p, q} has a corner at p.
// So a point's corner list (about 6 corners on a closed mesh) holds everything its fans depend on,
// and the union-find runs on a few local indices instead of 4.8 M corners scattered over memory.
#include "marble/mesh/vertex_normals.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "marble/core/parallel_for.h"
#include "marble/mesh/corner_angle.h"
#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/point_ids.h"

namespace marble {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;
// Points with at most this many corners find their edges by comparing all pairs.
constexpr uint32_t kSmallPoint = 16;
// Points a thread takes at a time in the point pass: large enough that the shared counter is
// rare, small enough to even out the threads' shares.
constexpr size_t kPointBlock = 4096;

uint32_t nextCorner(uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
uint32_t previousCorner(uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

glm::vec3 unitOr(glm::vec3 v, glm::vec3 fallback) {
  const float len = glm::length(v);
  return std::isfinite(len) && len > 0.0f ? v / len : fallback;
}

// Sorts a small array (a point's edge ends or vertices: a handful) by insertion, a large one (a
// fan of thousands of triangles) by std::sort. Stable for the small ones; the large ones' keys
// carry their position, so they are unique.
template <class T>
void sortSmall(T* first, T* last) {
  if (last - first > 24) {
    std::sort(first, last);
    return;
  }
  for (T* i = first + 1; i < last; ++i)
    for (T* k = i; k > first && k[-1] > k[0]; --k) std::swap(k[-1], k[0]);
}

// A copy of a render vertex for a fan other than the vertex's first: made at `corner` (the first
// corner of that vertex in that fan), used by the corners that name it.
struct Copy {
  uint32_t corner;
  uint32_t vertex;
  glm::vec3 normal;
};
struct CopyUse {
  uint32_t corner;
  uint32_t madeAt;  // the Copy's corner
};

// What one thread's points leave for the serial step: the copies they make, the corners that
// use them, and the duplicate triangles found (each by the point of its first corner).
struct PointsOutput {
  std::vector<Copy> copies;
  std::vector<CopyUse> uses;
  std::vector<uint32_t> duplicates;
};

// What the passes after the first need of a usable triangle, in one record so that a corner costs
// one cache miss, not four (its point, its neighbours' points, its vertex, normal and angle).
struct Triangle {
  uint32_t point[3];  // point[0] == kNone: not filed (a repeated point, an index out of range)
  uint32_t vertex[3];
  glm::vec3 normal;
  float angle[3];  // angle[0] == kNoArea: filed for the duplicate check only (zero or non-finite area)
};
// A corner angle is atan2 of a positive length: in (0, pi]. A negative one marks a triangle that
// adds nothing to the normals (main's "unusable": zero or non-finite area) but has three distinct
// points, so it is still filed under them: the duplicate check by points sees every such triangle.
constexpr float kNoArea = -1.0f;

// Both cache lines a record may span (48 bytes at a 48-byte stride: half of them cross a 64-byte
// line, and the point pass reads all of a record: points first, normal and angles after).
void prefetchRecord(const Triangle* t) {
  __builtin_prefetch(t);
  __builtin_prefetch(reinterpret_cast<const char*>(t) + sizeof(Triangle) - 1);
}

struct Corners {
  const Triangle* triangles;
  float cosCrease;
  bool noCrease;
  bool dropDuplicates;
  uint32_t point(uint32_t c) const { return triangles[c / 3].point[c % 3]; }
  uint32_t vertex(uint32_t c) const { return triangles[c / 3].vertex[c % 3]; }
  const glm::vec3& normal(uint32_t c) const { return triangles[c / 3].normal; }
};

// Scratch arrays of one thread, reused from point to point.
struct Scratch {
  // Edge ends of a point with more than kSmallPoint corners: (other point << 33) | (incoming << 32)
  // | local index (point ids are < the vertex count, at most kMaxVertices = 5e7 < 2^31).
  std::vector<uint64_t> ends;
  std::vector<uint32_t> parent;   // union-find over the point's local indices
  std::vector<uint32_t> fanOf;    // local index -> fan (local)
  std::vector<glm::vec3> fanSum;  // per local fan
  std::vector<uint64_t> vertexFan;  // (vertex << 32) | (local fan << 16) | local index
  std::vector<uint8_t> takesPart;   // per local index: neither a duplicate triangle's nor arealess
  std::vector<uint32_t> kept;       // the point's corners that take part, when some do not
  std::vector<std::pair<uint64_t, uint32_t>> triangleKeys;  // (next point, previous point), local index
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// The fans of one point whose usable corners are list[0..k) (ascending), their normals, and its
// vertices: the first fan each vertex meets (in corner order) keeps the vertex; every other
// (vertex, fan) pair is a copy, made at its first corner.
// `knownTo` and `knownFrom`, when given (k <= kSmallPoint), are each corner's next and previous
// point, found by the caller already.
void settleFans(const Corners& in, const uint32_t* list, uint32_t k, Scratch& s, std::vector<glm::vec3>& normals,
                PointsOutput& out, const uint32_t* knownTo = nullptr, const uint32_t* knownFrom = nullptr) {
  s.parent.resize(k);
  for (uint32_t i = 0; i < k; ++i) s.parent[i] = i;
  if (in.noCrease) {
    for (uint32_t i = 1; i < k; ++i) s.parent[i] = 0;
  } else {
    // Each corner uses two edges at this point: out to the next corner's point (forward) and in
    // from the previous one's. An edge {p, q} is smooth when exactly two of p's corners use it, one
    // each way, and their faces are within the crease angle (Blender's rule); the two corners then
    // join. (Every triangle that uses the edge has a corner at p and uses it once: its points are
    // distinct.)
    auto join = [&](uint32_t i, uint32_t j) {
      if (glm::dot(in.normal(list[i]), in.normal(list[j])) >= in.cosCrease) {
        const uint32_t ri = findRoot(s.parent, i), rj = findRoot(s.parent, j);
        if (ri != rj) s.parent[std::max(ri, rj)] = std::min(ri, rj);
      }
    };
    if (k <= kSmallPoint) {
      // The common case (a closed mesh has ~6 corners a point): each corner's forward edge
      // compared with every corner's two edges, without branches; a sort would cost more.
      uint32_t ownTo[kSmallPoint], ownFrom[kSmallPoint];
      if (!knownTo) {
        for (uint32_t i = 0; i < k; ++i) {
          const Triangle& t = in.triangles[list[i] / 3];
          const uint32_t slot = list[i] % 3;
          ownTo[i] = t.point[slot == 2 ? 0 : slot + 1];
          ownFrom[i] = t.point[slot == 0 ? 2 : slot - 1];
        }
      }
      const uint32_t* to = knownTo ? knownTo : ownTo;
      const uint32_t* from = knownFrom ? knownFrom : ownFrom;
      for (uint32_t i = 0; i < k; ++i) {
        uint32_t forward = 0, incoming = 0, j = 0;
        for (uint32_t m = 0; m < k; ++m) {
          forward += to[m] == to[i];
          incoming += from[m] == to[i];
          j = from[m] == to[i] ? m : j;
        }
        if (forward == 1 && incoming == 1) join(i, j);
      }
    } else {
    s.ends.resize(2 * size_t{k});
    for (uint32_t i = 0; i < k; ++i) {
      const uint32_t c = list[i];
      s.ends[2 * i] = (uint64_t{in.point(nextCorner(c))} << 33) | i;
      s.ends[2 * i + 1] = (uint64_t{in.point(previousCorner(c))} << 33) | (uint64_t{1} << 32) | i;
    }
    uint64_t* const ends = s.ends.data();
    sortSmall(ends, ends + 2 * k);
    for (uint32_t a = 0; a < 2 * k;) {
      uint32_t b = a + 1;
      while (b < 2 * k && (ends[b] >> 33) == (ends[a] >> 33)) ++b;
      // Sorted by direction within the edge: a forward use, then an incoming one.
      if (b - a == 2 && ((ends[a] >> 32) & 1) == 0 && ((ends[a + 1] >> 32) & 1) == 1) {
        join(static_cast<uint32_t>(ends[a]), static_cast<uint32_t>(ends[a + 1]));
      }
      a = b;
    }
    }
  }

  // Fans numbered by their lowest corner; each fan's sum in corner order (as one pass over all
  // corners in file order would add them).
  s.fanOf.resize(k);
  s.fanSum.clear();
  for (uint32_t i = 0; i < k; ++i) {
    const uint32_t root = findRoot(s.parent, i);
    if (root == i) {
      s.fanOf[i] = static_cast<uint32_t>(s.fanSum.size());
      s.fanSum.emplace_back(0.0f);
    } else {
      s.fanOf[i] = s.fanOf[root];
    }
    const uint32_t c = list[i];
    const Triangle& t = in.triangles[c / 3];
    s.fanSum[s.fanOf[i]] += t.normal * t.angle[c % 3];
  }

  // The common case: one fan, one vertex.
  const uint32_t v0 = in.vertex(list[0]);
  bool oneVertex = true;
  for (uint32_t i = 1; i < k && oneVertex; ++i) oneVertex = in.vertex(list[i]) == v0;
  if (s.fanSum.size() == 1 && oneVertex) {
    normals[v0] = unitOr(s.fanSum[0], in.normal(list[0]));
    return;
  }

  // (vertex, fan, local index) sorted: each pair's first corner leads its run, and a vertex's
  // runs follow one another.
  s.vertexFan.resize(k);
  for (uint32_t i = 0; i < k; ++i) s.vertexFan[i] = (uint64_t{in.vertex(list[i])} << 32) | (uint64_t{s.fanOf[i]} << 16) | i;
  if (k > 0xFFFF || s.fanSum.size() > 0xFFFF) {
    // More than 65,535 corners at one point: keys too wide for one word; sort pairs instead.
    std::vector<std::pair<uint64_t, uint32_t>> wide(k);
    for (uint32_t i = 0; i < k; ++i) wide[i] = {(uint64_t{in.vertex(list[i])} << 32) | s.fanOf[i], i};
    std::sort(wide.begin(), wide.end());
    for (uint32_t a = 0; a < k;) {
      const uint32_t v = static_cast<uint32_t>(wide[a].first >> 32);
      // The vertex's first corner: the least local index over its runs.
      uint32_t b = a, keepFan = kNone, keepAt = kNone;
      for (; b < k && (wide[b].first >> 32) == v; ++b)
        if (wide[b].second < keepAt) keepAt = wide[b].second, keepFan = static_cast<uint32_t>(wide[b].first);
      normals[v] = unitOr(s.fanSum[keepFan], in.normal(list[keepAt]));
      for (uint32_t r = a; r < b;) {
        uint32_t e = r + 1;
        while (e < b && wide[e].first == wide[r].first) ++e;
        const uint32_t fan = static_cast<uint32_t>(wide[r].first);
        if (fan != keepFan) {
          const uint32_t at = list[wide[r].second];
          out.copies.push_back({at, v, unitOr(s.fanSum[fan], in.normal(at))});
          for (uint32_t m = r + 1; m < e; ++m) out.uses.push_back({list[wide[m].second], at});
        }
        r = e;
      }
      a = b;
    }
    return;
  }
  uint64_t* const keys = s.vertexFan.data();
  sortSmall(keys, keys + k);
  auto vertexOf = [](uint64_t key) { return static_cast<uint32_t>(key >> 32); };
  auto fanOfKey = [](uint64_t key) { return static_cast<uint32_t>(key >> 16) & 0xFFFFu; };
  auto localOf = [](uint64_t key) { return static_cast<uint32_t>(key) & 0xFFFFu; };
  for (uint32_t a = 0; a < k;) {
    const uint32_t v = vertexOf(keys[a]);
    uint32_t b = a, keepFan = kNone, keepAt = kNone;
    for (; b < k && vertexOf(keys[b]) == v; ++b)
      if (localOf(keys[b]) < keepAt) keepAt = localOf(keys[b]), keepFan = fanOfKey(keys[b]);
    normals[v] = unitOr(s.fanSum[keepFan], in.normal(list[keepAt]));
    for (uint32_t r = a; r < b;) {
      const uint32_t fan = fanOfKey(keys[r]);
      uint32_t e = r + 1;
      while (e < b && fanOfKey(keys[e]) == fan) ++e;
      if (fan != keepFan) {
        const uint32_t at = list[localOf(keys[r])];
        out.copies.push_back({at, v, unitOr(s.fanSum[fan], in.normal(at))});
        for (uint32_t m = r + 1; m < e; ++m) out.uses.push_back({list[localOf(keys[m])], at});
      }
      r = e;
    }
    a = b;
  }
}

// One point whose filed corners are list[0..k) (ascending): drops the corners of duplicate
// triangles (when asked) and of triangles without area, then settles the rest (settleFans).
//
// The duplicate check, point by point: two triangles with three distinct points are the same
// triangle (duplicate_triangles.h: the same points in the same cyclic order) exactly when, at a
// point p they share, both go on to the same next point and come from the same previous one. Both
// have a corner at each of their three points, so every one of the three sees the pair in its own
// list, and each finds the same answer alone: a corner is dropped when an earlier corner of the
// list (an earlier triangle: each triangle has one corner here) has the same two neighbours. The
// first of each key is kept, as removeDuplicateTriangles keeps it; the point of a triangle's
// first corner reports it.
void settlePoint(const Corners& in, const uint32_t* list, uint32_t k, Scratch& s, std::vector<glm::vec3>& normals,
                 PointsOutput& out) {
  auto neighbours = [&](uint32_t c) {  // (next point, previous point)
    const Triangle& t = in.triangles[c / 3];
    const uint32_t slot = c % 3;
    return std::pair{t.point[slot == 2 ? 0 : slot + 1], t.point[slot == 0 ? 2 : slot - 1]};
  };
  auto hasArea = [&](uint32_t c) { return in.triangles[c / 3].angle[0] != kNoArea; };
  if (k <= kSmallPoint) {
    // The common case: the neighbours found once, for the repeats here and the edges in settleFans;
    // bit i of a mask for corner i.
    uint32_t to[kSmallPoint], from[kSmallPoint];
    for (uint32_t i = 0; i < k; ++i) std::tie(to[i], from[i]) = neighbours(list[i]);
    uint32_t repeats = 0, arealess = 0;
    if (in.dropDuplicates)
      for (uint32_t i = 1; i < k; ++i) {
        bool repeat = false;
        for (uint32_t m = 0; m < i; ++m) repeat |= to[m] == to[i] && from[m] == from[i];
        repeats |= uint32_t{repeat} << i;
      }
    for (uint32_t i = 0; i < k; ++i) arealess |= uint32_t{!hasArea(list[i])} << i;
    if ((repeats | arealess) == 0) {
      settleFans(in, list, k, s, normals, out, to, from);
      return;
    }
    s.kept.clear();
    for (uint32_t i = 0; i < k; ++i) {
      if ((repeats >> i & 1) && list[i] % 3 == 0) out.duplicates.push_back(list[i] / 3);
      if (((repeats | arealess) >> i & 1) == 0) s.kept.push_back(list[i]);
    }
  } else {
    // Many corners (a fan of thousands of triangles): the repeats found by sorting; the first of
    // each key sorts first (the local index breaks ties).
    s.takesPart.assign(k, 1);
    if (in.dropDuplicates) {
      s.triangleKeys.resize(k);
      for (uint32_t i = 0; i < k; ++i) {
        const auto [to, from] = neighbours(list[i]);
        s.triangleKeys[i] = {(uint64_t{to} << 32) | from, i};
      }
      std::sort(s.triangleKeys.begin(), s.triangleKeys.end());
      for (uint32_t a = 1; a < k; ++a)
        if (s.triangleKeys[a].first == s.triangleKeys[a - 1].first) s.takesPart[s.triangleKeys[a].second] = 0;
      for (uint32_t i = 0; i < k; ++i)
        if (!s.takesPart[i] && list[i] % 3 == 0) out.duplicates.push_back(list[i] / 3);
    }
    bool all = true;
    for (uint32_t i = 0; i < k; ++i) {
      s.takesPart[i] &= hasArea(list[i]) ? 1 : 0;
      all &= s.takesPart[i] != 0;
    }
    if (all) {
      settleFans(in, list, k, s, normals, out);
      return;
    }
    s.kept.clear();
    for (uint32_t i = 0; i < k; ++i)
      if (s.takesPart[i]) s.kept.push_back(list[i]);
  }
  if (!s.kept.empty()) settleFans(in, s.kept.data(), static_cast<uint32_t>(s.kept.size()), s, normals, out);
}

size_t computeNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& point, bool dropDuplicates,
                      PageBuffer* recycled) {
  const size_t nv = mesh.positions.size();
  const size_t corners = mesh.indices.size() / 3 * 3;
  const size_t triangles = corners / 3;
  if (point.size() != nv) throw std::invalid_argument("computeVertexNormals: one point id per vertex expected");

  // One range of triangles per thread for the first two passes; blocks of points for the third.
  const unsigned threads = workerThreadCount(corners, 150000);
  auto onEachThread = [&](auto&& work) {
    parallelFor(threads, 1, [&](size_t begin, size_t end) {
      for (size_t t = begin; t < end; ++t) work(static_cast<unsigned>(t));
    });
  };

  // Pass 1, per triangle: its record (unit normal, each corner's angle, point and vertex; point[0] =
  // kNone for a triangle with a repeated point or an index out of range, which is not filed;
  // angle[0] = kNoArea for one without area, filed for the duplicate check only); per thread, the
  // filed corners counted by point, and the triangles not filed (the duplicate check sees them
  // apart).
  // Fresh arrays of this size are left unset (make_unique_for_overwrite) where every element the
  // later passes read is written first: zeroing 77 MB (1.6 M triangles) on the calling thread
  // faulted in every page there, before the threads wrote them again. The records go into
  // `recycled` when given (pages faulted in already: page_buffer.h).
  PageBuffer ownRecords;
  PageBuffer& records = recycled ? *recycled : ownRecords;
  records.resize(triangles * sizeof(Triangle));
  Triangle* const triangle = reinterpret_cast<Triangle*>(records.data());
  std::uninitialized_default_construct_n(triangle, triangles);  // trivial: no code, only their lifetimes
  std::vector<std::vector<uint32_t>> count(threads), notFiled(threads);
  constexpr size_t kAhead = 8;
  onEachThread([&](unsigned thread) {
    std::vector<uint32_t>& n = count[thread];
    n.assign(nv, 0);
    for (size_t t = triangles * thread / threads, end = triangles * (thread + 1) / threads; t < end; ++t) {
      // The corners' points and positions of a triangle a few ahead, prefetched: the indices are
      // read in order, but the vertices they name are scattered over arrays larger than the caches.
      if (t + kAhead < end) {
        const uint32_t* ahead = &mesh.indices[3 * (t + kAhead)];
        for (int k = 0; k < 3; ++k)
          if (ahead[k] < nv) {
            __builtin_prefetch(&point[ahead[k]]);
            __builtin_prefetch(&mesh.positions[ahead[k]]);
          }
        // The counts of a triangle half as far ahead, whose points were prefetched above then.
        const uint32_t* half = &mesh.indices[3 * (t + kAhead / 2)];
        for (int k = 0; k < 3; ++k)
          if (half[k] < nv) __builtin_prefetch(&n[point[half[k]]], 1);
      }
      Triangle& out = triangle[t];
      out.point[0] = kNone;
      const uint32_t* v = &mesh.indices[3 * t];
      if (v[0] >= nv || v[1] >= nv || v[2] >= nv) {
        if (dropDuplicates) notFiled[thread].push_back(static_cast<uint32_t>(t));
        continue;
      }
      const uint32_t q[3] = {point[v[0]], point[v[1]], point[v[2]]};
      if (q[0] == q[1] || q[1] == q[2] || q[0] == q[2]) {
        if (dropDuplicates) notFiled[thread].push_back(static_cast<uint32_t>(t));
        continue;
      }
      const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[v[0]]), glm::dvec3(mesh.positions[v[1]]),
                               glm::dvec3(mesh.positions[v[2]])};
      const glm::dvec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
      const double len = glm::length(normal);
      const bool hasArea = len > 0.0 && std::isfinite(len);
      if (!hasArea && !dropDuplicates) continue;
      if (hasArea) out.normal = glm::vec3(normal / len);
      for (int k = 0; k < 3; ++k) {
        // |e1 x e2| is twice the area at every corner: the face's `len` (equal up to rounding).
        if (hasArea)
          out.angle[k] = static_cast<float>(atan2OfLength(len, glm::dot(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k])));
        out.point[k] = q[k];
        out.vertex[k] = v[k];
        ++n[q[k]];
      }
      if (!hasArea) out.angle[0] = kNoArea;
    }
  });

  // Where each thread's corners of each point go: points in order, within a point the threads in
  // order (so every list stays in corner order). `count` becomes each thread's next slot.
  const std::unique_ptr<uint32_t[]> pointStart = std::make_unique_for_overwrite<uint32_t[]>(nv + 1);
  {
    uint32_t total = 0;
    for (size_t p = 0; p < nv; ++p) {
      pointStart[p] = total;
      for (unsigned t = 0; t < threads; ++t) {
        const uint32_t n = count[t][p];
        count[t][p] = total;
        total += n;
      }
    }
    pointStart[nv] = total;
  }
  // Every slot is written: the counts above are the usable corners filed below.
  const std::unique_ptr<uint32_t[]> byPoint = std::make_unique_for_overwrite<uint32_t[]>(pointStart[nv]);
  onEachThread([&](unsigned thread) {
    uint32_t* const slot = count[thread].data();
    for (size_t t = triangles * thread / threads, end = triangles * (thread + 1) / threads; t < end; ++t) {
      if (t + kAhead < end && triangle[t + kAhead].point[0] != kNone)
        for (uint32_t k = 0; k < 3; ++k) __builtin_prefetch(&slot[triangle[t + kAhead].point[k]], 1);
      const Triangle& tri = triangle[t];
      if (tri.point[0] == kNone) continue;
      for (uint32_t k = 0; k < 3; ++k) byPoint[slot[tri.point[k]]++] = static_cast<uint32_t>(3 * t + k);
    }
  });
  { std::vector<std::vector<uint32_t>>().swap(count); }

  // Pass 3, per point: fans, normals, vertices. The threads take blocks of points in turn as they
  // finish (the cost per corner varies along the ids: a subdivided mesh's first points, the coarse
  // mesh's, have their corners spread over the file); each writes only its points' vertices' normals.
  // Room for the copies made below (capacityForCreaseCopies), so that appending them does not move
  // the array.
  std::vector<glm::vec3> normals;
  normals.reserve(capacityForCreaseCopies(nv));
  normals.resize(nv, glm::vec3(0.0f, 1.0f, 0.0f));
  std::vector<PointsOutput> outputs(threads);
  const Corners in{triangle,
                   static_cast<float>(std::cos(creaseAngleDeg * std::numbers::pi / 180.0)),
                   creaseAngleDeg >= kNoCreaseDeg, dropDuplicates};
  std::atomic<size_t> nextBlock{0};
  onEachThread([&](unsigned thread) {
    Scratch scratch;
    for (size_t begin; (begin = nextBlock.fetch_add(kPointBlock, std::memory_order_relaxed)) < nv;)
      for (size_t p = begin, end = std::min(nv, begin + kPointBlock); p < end; ++p) {
        // The records of the corners of a point two ahead, prefetched: a point's corners are
        // scattered over the 77 MB of records (one miss each, most of this pass's time).
        if (p + 2 < end)
          for (uint32_t i = pointStart[p + 2], e = pointStart[p + 3]; i < e && i < pointStart[p + 2] + kSmallPoint; ++i)
            prefetchRecord(&triangle[byPoint[i] / 3]);
        const uint32_t k = pointStart[p + 1] - pointStart[p];
        if (k != 0) settlePoint(in, byPoint.get() + pointStart[p], k, scratch, normals, outputs[thread]);
      }
  });

  // The copies, numbered in the order of the corners that make them (as one pass in corner order
  // would meet them): few (the crease edges' and seams' vertices), so on one thread.
  std::vector<Copy> copies;
  std::vector<CopyUse> uses;
  for (PointsOutput& o : outputs) {
    copies.insert(copies.end(), o.copies.begin(), o.copies.end());
    uses.insert(uses.end(), o.uses.begin(), o.uses.end());
  }
  std::sort(copies.begin(), copies.end(), [](const Copy& a, const Copy& b) { return a.corner < b.corner; });
  const bool hasTexcoords = mesh.texcoords.size() == nv;
  mesh.positions.reserve(nv + copies.size());
  if (hasTexcoords) mesh.texcoords.reserve(nv + copies.size());
  normals.reserve(nv + copies.size());
  for (const Copy& copy : copies) {
    mesh.indices[copy.corner] = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(mesh.positions[copy.vertex]);  // reserved: no reallocation
    if (hasTexcoords) mesh.texcoords.push_back(mesh.texcoords[copy.vertex]);
    normals.push_back(copy.normal);
  }
  // A use's copy was made at corner `madeAt`, whose index now names the copy.
  for (const CopyUse& use : uses) mesh.indices[use.corner] = mesh.indices[use.madeAt];
  mesh.normals = std::move(normals);
  if (!dropDuplicates) return 0;

  // The duplicates: those the points found, and among the triangles not filed (a repeated point
  // or an index out of range: rare) those removeDuplicateTriangles finds. Their keys hold a
  // repeated point or an index out of range, so they never equal a filed triangle's key.
  std::vector<uint32_t> duplicates;
  for (const PointsOutput& o : outputs) duplicates.insert(duplicates.end(), o.duplicates.begin(), o.duplicates.end());
  Mesh unfiled;
  std::vector<uint32_t> unfiledAt;  // their triangle numbers, ascending
  for (const std::vector<uint32_t>& list : notFiled)
    for (const uint32_t t : list) {
      unfiledAt.push_back(t);
      unfiled.indices.insert(unfiled.indices.end(), {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
    }
  for (const uint32_t u : duplicateTriangles(unfiled, point, 1)) duplicates.push_back(unfiledAt[u]);
  std::sort(duplicates.begin(), duplicates.end());
  return removeTriangles(mesh, duplicates);
}

}  // namespace

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg) {
  computeVertexNormals(mesh, creaseAngleDeg, pointIds(mesh.positions));
}

void computeVertexNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& point) {
  computeNormals(mesh, creaseAngleDeg, point, /*dropDuplicates=*/false, nullptr);
}

size_t removeDuplicatesAndComputeNormals(Mesh& mesh, float creaseAngleDeg, const std::vector<uint32_t>& point,
                                         PageBuffer* recycled) {
  return computeNormals(mesh, creaseAngleDeg, point, /*dropDuplicates=*/true, recycled);
}

}  // namespace marble
