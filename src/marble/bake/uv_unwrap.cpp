#include "marble/bake/uv_unwrap.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "marble/bake/uv_raster.h"
#include "marble/core/error.h"

namespace marble {
namespace {

constexpr uint32_t kNoChart = ~0u;

// Vertices at the same position get one id, so charts grow across seams a loader made for
// normals or texcoords (a crease split, an OBJ corner with its own vt).
std::vector<uint32_t> weldByPosition(const Mesh& mesh) {
  std::unordered_map<uint64_t, std::vector<uint32_t>> buckets;  // hash of the bits -> first ids
  std::vector<uint32_t> id(mesh.positions.size());
  buckets.reserve(mesh.positions.size());
  for (uint32_t i = 0; i < mesh.positions.size(); ++i) {
    uint32_t bits[3];
    std::memcpy(bits, &mesh.positions[i], sizeof bits);
    const uint64_t h = (uint64_t{bits[0]} * 0x9E3779B97F4A7C15ull) ^ (uint64_t{bits[1]} * 0xC2B2AE3D27D4EB4Full) ^
                       (uint64_t{bits[2]} * 0x165667B19E3779F9ull);
    auto& list = buckets[h];
    id[i] = i;
    for (uint32_t j : list)
      if (mesh.positions[j] == mesh.positions[i]) {
        id[i] = j;
        break;
      }
    if (id[i] == i) list.push_back(i);
  }
  return id;
}

// For each triangle edge k (t*3 + e, from corner e to e+1), the triangle across it, or ~0u when
// the edge is a border or is shared by more than two triangles (not manifold: charts stop there).
std::vector<uint32_t> edgeNeighbours(const Mesh& mesh, const std::vector<uint32_t>& weld) {
  const size_t triangles = mesh.triangleCount();
  struct Edge {
    uint64_t key;
    uint32_t half;
  };
  std::vector<Edge> edges;
  edges.reserve(triangles * 3);
  for (uint32_t t = 0; t < triangles; ++t)
    for (uint32_t e = 0; e < 3; ++e) {
      uint32_t a = weld[mesh.indices[t * 3 + e]], b = weld[mesh.indices[t * 3 + (e + 1) % 3]];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      edges.push_back({(uint64_t{a} << 32) | b, t * 3 + e});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.key != y.key ? x.key < y.key : x.half < y.half;
  });
  std::vector<uint32_t> across(triangles * 3, ~0u);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 2) {
      across[edges[i].half] = edges[i + 1].half / 3;
      across[edges[i + 1].half] = edges[i].half / 3;
    }
    i = j;
  }
  return across;
}

struct Chart {
  glm::vec3 axis;
  std::vector<uint32_t> triangles;
  glm::vec2 lo{0}, hi{0};  // bounding box of the projected, turned chart (object units)
  glm::vec2 u{1, 0}, v{0, 1};  // in-plane basis after turning to the principal axis
  bool rotated = false;        // packed turned by 90 degrees (taller than wide)
  glm::vec2 offset{0};         // packed place (texels, lower-left corner inside the padding)
};

// Two unit vectors spanning the plane perpendicular to `n`.
void planeBasis(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, t);
}

// Whether the chart's triangles, projected along `axis`, cover some point twice: rasterized on
// a grid fine enough that the mean triangle covers about 8 samples (a fold covers many).
bool projectionFolds(const Mesh& mesh, const std::vector<uint32_t>& tris, glm::vec3 axis) {
  glm::vec3 t, b;
  planeBasis(axis, t, b);
  std::vector<glm::vec2> p(tris.size() * 3);
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 v = mesh.positions[mesh.indices[tris[i] * 3 + k]];
      p[i * 3 + k] = glm::vec2(glm::dot(v, t), glm::dot(v, b));
      lo = glm::min(lo, p[i * 3 + k]);
      hi = glm::max(hi, p[i * 3 + k]);
    }
  const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(extent > 0)) return false;
  const int res = static_cast<int>(std::clamp(std::sqrt(8.0 * static_cast<double>(tris.size())) * 2.0, 16.0, 1024.0));
  std::vector<uint8_t> hits(static_cast<size_t>(res) * res, 0);
  bool folds = false;
  for (size_t i = 0; i < tris.size() && !folds; ++i) {
    glm::vec2 q[3];
    for (int k = 0; k < 3; ++k) q[k] = (p[i * 3 + k] - lo) / extent * 0.98f + 0.01f;
    rasterizeUvTriangle(q[0], q[1], q[2], res, [&](int x, int y, glm::vec3) {
      uint8_t& h = hits[static_cast<size_t>(y) * res + x];
      if (h) folds = true;
      h = 1;
    });
  }
  return folds;
}

// Shelf packing at `scale` texels per object unit: charts in the given order (tallest first),
// left to right, a new shelf when a row is full. Returns false if they do not fit in size^2.
bool packShelves(std::vector<Chart>& charts, const std::vector<uint32_t>& order, double scale, int size, int pad) {
  double x = 0, y = 0, shelf = 0;
  for (uint32_t c : order) {
    Chart& ch = charts[c];
    glm::dvec2 ext = glm::dvec2(ch.hi - ch.lo) * scale;
    if (ch.rotated) std::swap(ext.x, ext.y);
    const double w = std::ceil(ext.x) + 2.0 * pad, h = std::ceil(ext.y) + 2.0 * pad;
    if (w > size) return false;
    if (x + w > size) {
      y += shelf;
      x = 0;
      shelf = 0;
    }
    if (y + h > size) return false;
    ch.offset = glm::vec2(static_cast<float>(x + pad), static_cast<float>(y + pad));
    x += w;
    shelf = std::max(shelf, h);
  }
  return true;
}

// Where a point of the chart (in its projected, turned plane) lands inside the chart's box, in
// texels at `scale`; a quarter turn (not a mirror, so triangles keep their winding) for charts
// packed on their side.
glm::dvec2 localTexel(const Chart& ch, glm::vec2 planar, double scale) {
  const glm::dvec2 local = glm::dvec2(planar - ch.lo) * scale;
  if (!ch.rotated) return local;
  return {static_cast<double>(ch.hi.y - ch.lo.y) * scale - local.y, local.x};
}

// Skyline packing of the charts' own shapes: each chart's footprint (its triangles on a grid of
// `cell` texels, grown by the padding plus one cell for the grid's rounding) drops onto the
// skyline of what is placed, at the column that leaves it lowest (a Tetris drop). Tighter than
// shelves because irregular charts interlock instead of each taking its bounding box.
bool packSkyline(std::vector<Chart>& charts, const std::vector<uint32_t>& order, const std::vector<std::vector<glm::vec2>>& corners,
                 double scale, int size, int pad) {
  const int cell = size >= 1024 ? 2 : 1;
  const int W = size / cell;
  const int grow = (pad + cell - 1) / cell + 1;
  std::vector<int> sky(static_cast<size_t>(W), 0), bottom, top;
  std::vector<uint8_t> fp, tmp;
  constexpr int kEmpty = std::numeric_limits<int>::max();
  for (uint32_t c : order) {
    Chart& ch = charts[c];
    glm::dvec2 ext = glm::dvec2(ch.hi - ch.lo) * scale;
    if (ch.rotated) std::swap(ext.x, ext.y);
    const int fw = static_cast<int>(std::ceil(ext.x / cell)) + 2 * grow + 1, fh = static_cast<int>(std::ceil(ext.y / cell)) + 2 * grow + 1;
    if (fw > W || fh > W) return false;
    fp.assign(static_cast<size_t>(fw) * fh, 0);
    const int res = std::max(fw, fh);
    auto toGrid = [&](glm::vec2 planar) { return localTexel(ch, planar, scale) / static_cast<double>(cell) + static_cast<double>(grow); };
    const std::vector<glm::vec2>& tri = corners[c];
    for (size_t i = 0; i + 2 < tri.size(); i += 3) {
      glm::vec2 uv[3];
      for (int k = 0; k < 3; ++k) {
        const glm::dvec2 g = toGrid(tri[i + k]);
        const int gx = std::clamp(static_cast<int>(g.x), 0, fw - 1), gy = std::clamp(static_cast<int>(g.y), 0, fh - 1);
        fp[static_cast<size_t>(gy) * fw + gx] = 1;  // a vertex's cell, for slivers no centre falls in
        uv[k] = glm::vec2(static_cast<float>(g.x / res), static_cast<float>(1.0 - g.y / res));
      }
      rasterizeUvTriangle(uv[0], uv[1], uv[2], res, [&](int x, int y, glm::vec3) {
        if (x < fw && y < fh) fp[static_cast<size_t>(y) * fw + x] = 1;
      });
    }
    // Grow by `grow` cells: a max filter along rows, then along columns.
    tmp.assign(fp.size(), 0);
    for (int y = 0; y < fh; ++y)
      for (int x = 0; x < fw; ++x)
        if (fp[static_cast<size_t>(y) * fw + x])
          for (int k = std::max(0, x - grow); k <= std::min(fw - 1, x + grow); ++k) tmp[static_cast<size_t>(y) * fw + k] = 1;
    std::fill(fp.begin(), fp.end(), 0);
    for (int y = 0; y < fh; ++y)
      for (int x = 0; x < fw; ++x)
        if (tmp[static_cast<size_t>(y) * fw + x])
          for (int k = std::max(0, y - grow); k <= std::min(fh - 1, y + grow); ++k) fp[static_cast<size_t>(k) * fw + x] = 1;
    bottom.assign(static_cast<size_t>(fw), kEmpty);
    top.assign(static_cast<size_t>(fw), 0);
    for (int x = 0; x < fw; ++x)
      for (int y = 0; y < fh; ++y)
        if (fp[static_cast<size_t>(y) * fw + x]) {
          if (bottom[static_cast<size_t>(x)] == kEmpty) bottom[static_cast<size_t>(x)] = y;
          top[static_cast<size_t>(x)] = y + 1;
        }
    int bestY = kEmpty, bestX = 0;
    for (int X = 0; X + fw <= W; ++X) {
      int y = 0;
      for (int i = 0; i < fw && y < bestY; ++i)
        if (bottom[static_cast<size_t>(i)] != kEmpty) y = std::max(y, sky[static_cast<size_t>(X + i)] - bottom[static_cast<size_t>(i)]);
      if (y < bestY) {
        bestY = y;
        bestX = X;
      }
    }
    if (bestY == kEmpty || bestY + fh > W) return false;
    for (int i = 0; i < fw; ++i)
      if (bottom[static_cast<size_t>(i)] != kEmpty)
        sky[static_cast<size_t>(bestX + i)] = std::max(sky[static_cast<size_t>(bestX + i)], bestY + top[static_cast<size_t>(i)]);
    ch.offset = glm::vec2(static_cast<float>((bestX + grow) * cell), static_cast<float>((bestY + grow) * cell));
  }
  return true;
}

}  // namespace

UvUnwrapStats measureUvLayout(const Mesh& mesh) {
  UvUnwrapStats s;
  struct Sample {
    double density, weight;
  };
  std::vector<Sample> samples;
  double uvArea = 0, weightSum = 0, mean = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const double area3 = 0.5 * glm::length(glm::dvec3(glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a])));
    const glm::dvec2 e1 = glm::dvec2(mesh.texcoords[b] - mesh.texcoords[a]), e2 = glm::dvec2(mesh.texcoords[c] - mesh.texcoords[a]);
    const double area2 = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    uvArea += area2;
    if (area3 <= 0) continue;
    const double d = std::sqrt(area2 / area3);
    samples.push_back({d, area3});
    weightSum += area3;
    mean += d * area3;
  }
  s.packingEfficiency = uvArea;
  if (weightSum <= 0) return s;
  mean /= weightSum;
  double var = 0;
  for (const Sample& x : samples) var += x.weight * (x.density - mean) * (x.density - mean);
  s.densityCv = mean > 0 ? std::sqrt(var / weightSum) / mean : 0;
  std::sort(samples.begin(), samples.end(), [](const Sample& x, const Sample& y) { return x.density < y.density; });
  auto quantile = [&](double q) {
    double acc = 0;
    for (const Sample& x : samples) {
      acc += x.weight;
      if (acc >= q * weightSum) return x.density;
    }
    return samples.back().density;
  };
  const double median = quantile(0.5);
  if (median > 0) {
    s.densityP05 = quantile(0.05) / median;
    s.densityP95 = quantile(0.95) / median;
  }
  return s;
}

UvUnwrapResult unwrapUvs(const Mesh& mesh, const UvUnwrapOptions& options) {
  const size_t triangles = mesh.triangleCount();
  if (triangles == 0) throw InputError("mesh", "unwrap", "no triangles to unwrap");
  const std::vector<uint32_t> weld = weldByPosition(mesh);
  const std::vector<uint32_t> across = edgeNeighbours(mesh, weld);

  std::vector<glm::vec3> faceNormal(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[t * 3]], b = mesh.positions[mesh.indices[t * 3 + 1]],
                    c = mesh.positions[mesh.indices[t * 3 + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float len = glm::length(n);
    faceNormal[t] = len > 0 && std::isfinite(len) ? n / len : glm::vec3(0);  // zero: degenerate, fits any chart
  }

  // 1. Charts: breadth-first growth from the lowest unassigned triangle across manifold edges
  // while the face normal is within the cone around the seed's normal (dot >= cos). A chart
  // whose projection folds over itself (a tube that curls round, as the trefoil knot's does) is
  // grown again from the same seed with half the cone, until it does not.
  const float coneDeg = std::clamp(options.coneAngleDeg, 1.0f, 85.0f);
  std::vector<uint32_t> chartOf(triangles, kNoChart);
  std::vector<Chart> charts;
  std::vector<uint32_t> queue;
  for (uint32_t seed = 0; seed < triangles; ++seed) {
    if (chartOf[seed] != kNoChart) continue;
    const uint32_t id = static_cast<uint32_t>(charts.size());
    Chart chart;
    chart.axis = faceNormal[seed] == glm::vec3(0) ? glm::vec3(0, 1, 0) : faceNormal[seed];
    for (float cone = coneDeg;; cone *= 0.5f) {
      const float cosCone = std::cos(glm::radians(cone));
      queue.assign(1, seed);
      chartOf[seed] = id;
      for (size_t q = 0; q < queue.size(); ++q) {
        const uint32_t t = queue[q];
        for (uint32_t e = 0; e < 3; ++e) {
          const uint32_t n = across[t * 3 + e];
          if (n == ~0u || chartOf[n] != kNoChart) continue;
          if (glm::dot(faceNormal[n], chart.axis) < cosCone && faceNormal[n] != glm::vec3(0)) continue;
          chartOf[n] = id;
          queue.push_back(n);
        }
      }
      if (queue.size() == 1 || cone < 1.0f || !projectionFolds(mesh, queue, chart.axis)) break;
      for (uint32_t t : queue) chartOf[t] = kNoChart;
    }
    chart.triangles = queue;
    charts.push_back(std::move(chart));
  }

  // 2. New vertices: one per (input vertex, chart) pair, in order of first use.
  UvUnwrapResult out;
  std::unordered_map<uint64_t, uint32_t> vertexOf;
  vertexOf.reserve(mesh.positions.size() * 2);
  out.mesh.indices.resize(mesh.indices.size());
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.indices[t * 3 + k];
      const uint64_t key = (uint64_t{v} << 32) | chartOf[t];
      auto [it, inserted] = vertexOf.try_emplace(key, static_cast<uint32_t>(out.sourceVertex.size()));
      if (inserted) out.sourceVertex.push_back(v);
      out.mesh.indices[t * 3 + k] = it->second;
    }
  const size_t vertices = out.sourceVertex.size();
  std::vector<uint32_t> chartOfVertex(vertices);
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) chartOfVertex[out.mesh.indices[t * 3 + k]] = chartOf[t];

  // 3. Project each chart along its axis and turn it to its principal axis (smallest box, roughly).
  std::vector<glm::vec2> planar(vertices);
  std::vector<std::vector<uint32_t>> chartVertices(charts.size());
  for (uint32_t v = 0; v < vertices; ++v) chartVertices[chartOfVertex[v]].push_back(v);
  for (size_t c = 0; c < charts.size(); ++c) {
    Chart& ch = charts[c];
    glm::vec3 t, b;
    planeBasis(ch.axis, t, b);
    glm::dvec2 mean(0);
    for (uint32_t v : chartVertices[c]) {
      const glm::vec3 p = mesh.positions[out.sourceVertex[v]];
      planar[v] = glm::vec2(glm::dot(p, t), glm::dot(p, b));
      mean += glm::dvec2(planar[v]);
    }
    mean /= static_cast<double>(chartVertices[c].size());
    double sxx = 0, sxy = 0, syy = 0;
    for (uint32_t v : chartVertices[c]) {
      const glm::dvec2 d = glm::dvec2(planar[v]) - mean;
      sxx += d.x * d.x;
      sxy += d.x * d.y;
      syy += d.y * d.y;
    }
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // principal axis of the points
    ch.u = glm::vec2(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    ch.v = glm::vec2(-ch.u.y, ch.u.x);
    ch.lo = glm::vec2(std::numeric_limits<float>::max());
    ch.hi = glm::vec2(std::numeric_limits<float>::lowest());
    for (uint32_t v : chartVertices[c]) {
      planar[v] = glm::vec2(glm::dot(planar[v], ch.u), glm::dot(planar[v], ch.v));
      ch.lo = glm::min(ch.lo, planar[v]);
      ch.hi = glm::max(ch.hi, planar[v]);
    }
    const glm::vec2 ext = ch.hi - ch.lo;
    ch.rotated = ext.y > ext.x;
  }

  // 4. Pack at one scale for all charts: the largest that fits, by bisection.
  const int size = options.textureSize, pad = options.paddingTexels;
  std::vector<uint32_t> order(charts.size());
  std::iota(order.begin(), order.end(), 0u);
  auto packedHeight = [&](uint32_t c) {
    const glm::vec2 e = charts[c].hi - charts[c].lo;
    return charts[c].rotated ? e.x : e.y;
  };
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return packedHeight(a) > packedHeight(b); });
  double surface = 0;
  for (size_t t = 0; t < triangles; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[t * 3]], b = mesh.positions[mesh.indices[t * 3 + 1]],
                    c = mesh.positions[mesh.indices[t * 3 + 2]];
    surface += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  double lo = 0, hi = surface > 0 ? 2.0 * size / std::sqrt(surface) : 1.0;  // hi: the whole square at 100%, x2
  while (packShelves(charts, order, hi, size, pad)) hi *= 2;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (packShelves(charts, order, mid, size, pad) ? lo : hi) = mid;
  }
  if (!(lo > 0) || !packShelves(charts, order, lo, size, pad))
    throw InputError(options.source, "unwrap", std::to_string(charts.size()) + " charts do not fit a " + std::to_string(size) +
                                                   "-texel texture with " + std::to_string(pad) + " texels of padding (a larger --size fits them)");
  // Then the charts' own shapes on a skyline, at the largest scale that fits (bisection from the
  // shelves' scale up); the shelves stay when the skyline does no better.
  std::vector<std::vector<glm::vec2>> corners(charts.size());
  for (size_t c = 0; c < charts.size(); ++c)
    for (uint32_t t : charts[c].triangles)
      for (int k = 0; k < 3; ++k) corners[c].push_back(planar[out.mesh.indices[t * 3 + k]]);
  double scale = lo;
  if (packSkyline(charts, order, corners, lo, size, pad)) {
    double good = lo, bad = 4.0 * lo;
    while (packSkyline(charts, order, corners, bad, size, pad)) bad *= 2;
    for (int i = 0; i < 12; ++i) {
      const double mid = 0.5 * (good + bad);
      (packSkyline(charts, order, corners, mid, size, pad) ? good : bad) = mid;
    }
    scale = good;
    packSkyline(charts, order, corners, scale, size, pad);
  } else {
    packShelves(charts, order, scale, size, pad);
  }

  out.mesh.positions.resize(vertices);
  out.mesh.texcoords.resize(vertices);
  if (!mesh.normals.empty()) out.mesh.normals.resize(vertices);
  for (uint32_t v = 0; v < vertices; ++v) {
    const Chart& ch = charts[chartOfVertex[v]];
    const glm::dvec2 texel = glm::dvec2(ch.offset) + localTexel(ch, planar[v], scale);
    out.mesh.texcoords[v] = glm::vec2(texel / static_cast<double>(size));
    out.mesh.positions[v] = mesh.positions[out.sourceVertex[v]];
    if (!mesh.normals.empty()) out.mesh.normals[v] = mesh.normals[out.sourceVertex[v]];
  }
  out.stats = measureUvLayout(out.mesh);
  out.stats.charts = static_cast<int>(charts.size());
  return out;
}

}  // namespace marble
