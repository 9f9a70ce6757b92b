#include "marble/bake/uv_raster.h"

#include <algorithm>
#include <cmath>

namespace marble {
namespace {

// Edge function of the directed edge a->b at p, computed from the endpoints in one canonical
// order and negated for the other direction: the two triangles sharing an edge then get exactly
// opposite values, so the tie rule below gives a sample on the edge to exactly one of them.
double edgeFunction(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const bool swapped = (b.x < a.x) || (b.x == a.x && b.y < a.y);
  if (swapped) std::swap(a, b);
  const double e = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  return swapped ? -e : e;
}

// Top-left rule for a sample exactly on edge a->b (winding normalized to positive area).
bool ownsTie(glm::dvec2 a, glm::dvec2 b) {
  const double dy = b.y - a.y, dx = b.x - a.x;
  return dy > 0 || (dy == 0 && dx < 0);
}

bool inside(double e, bool tieOwned) { return e > 0 || (e == 0 && tieOwned); }

}  // namespace

void rasterizeUvTriangle(glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2, int res,
                         const std::function<void(int, int, glm::vec3)>& visit, glm::vec2 offset) {
  const double r = res;
  glm::dvec2 p[3] = {{uv0.x * r, (1.0 - uv0.y) * r}, {uv1.x * r, (1.0 - uv1.y) * r}, {uv2.x * r, (1.0 - uv2.y) * r}};
  int order[3] = {0, 1, 2};
  double area = edgeFunction(p[0], p[1], p[2]);
  if (!(std::abs(area) > 0)) return;  // degenerate (or NaN): covers no sample
  if (area < 0) {
    std::swap(p[1], p[2]);
    std::swap(order[1], order[2]);
    area = -area;
  }
  const double minX = std::min({p[0].x, p[1].x, p[2].x}), maxX = std::max({p[0].x, p[1].x, p[2].x});
  const double minY = std::min({p[0].y, p[1].y, p[2].y}), maxY = std::max({p[0].y, p[1].y, p[2].y});
  const double ox = offset.x, oy = offset.y;
  const int x0 = std::max(0, static_cast<int>(std::floor(minX - ox))), x1 = std::min(res - 1, static_cast<int>(std::ceil(maxX - ox)));
  const int y0 = std::max(0, static_cast<int>(std::floor(minY - oy))), y1 = std::min(res - 1, static_cast<int>(std::ceil(maxY - oy)));
  const bool tie0 = ownsTie(p[1], p[2]), tie1 = ownsTie(p[2], p[0]), tie2 = ownsTie(p[0], p[1]);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 s(x + ox, y + oy);
      const double w0 = edgeFunction(p[1], p[2], s), w1 = edgeFunction(p[2], p[0], s), w2 = edgeFunction(p[0], p[1], s);
      if (!inside(w0, tie0) || !inside(w1, tie1) || !inside(w2, tie2)) continue;
      double b[3];
      b[order[0]] = w0 / area;
      b[order[1]] = w1 / area;
      b[order[2]] = w2 / area;
      visit(x, y, glm::vec3(static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2])));
    }
  }
}

UvOverlap measureUvOverlap(const Mesh& mesh, int res) {
  UvOverlap out;
  std::vector<uint8_t> hits(static_cast<size_t>(res) * res, 0);
  const auto& uv = mesh.texcoords;
  auto outside = [](glm::vec2 t) { return !(t.x >= 0 && t.x <= 1 && t.y >= 0 && t.y <= 1); };
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec2 a = uv[mesh.indices[t]], b = uv[mesh.indices[t + 1]], c = uv[mesh.indices[t + 2]];
    if (outside(a) || outside(b) || outside(c)) ++out.outsideTriangles;
    rasterizeUvTriangle(a, b, c, res, [&](int x, int y, glm::vec3) {
      uint8_t& h = hits[static_cast<size_t>(y) * res + x];
      if (h < 2) ++h;
    });
  }
  for (uint8_t h : hits) {
    out.coveredSamples += h >= 1;
    out.overlapSamples += h >= 2;
  }
  return out;
}

}  // namespace marble
