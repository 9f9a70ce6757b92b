#include "marble/render/screen_tiles.h"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace marble {

OccupancyGrid::OccupancyGrid(const Mesh& mesh) {
  if (mesh.positions.empty() || mesh.indices.size() < 3) return;
  glm::vec3 lo = mesh.positions.front(), hi = lo;
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // A flat mesh still gets cells of some thickness.
  cellSize_ = glm::max(hi - lo, glm::vec3(1e-4f)) / static_cast<float>(kCells);
  auto cellOf = [&](const glm::vec3& p) {
    return glm::clamp(glm::ivec3(glm::floor((p - lo) / cellSize_)), glm::ivec3(0), glm::ivec3(kCells - 1));
  };
  std::vector<uint8_t> occupied(static_cast<size_t>(kCells) * kCells * kCells, 0);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3& a = mesh.positions[mesh.indices[t]];
    const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
    const glm::ivec3 c0 = cellOf(glm::min(a, glm::min(b, c))), c1 = cellOf(glm::max(a, glm::max(b, c)));
    for (int z = c0.z; z <= c1.z; ++z)
      for (int y = c0.y; y <= c1.y; ++y)
        for (int x = c0.x; x <= c1.x; ++x) occupied[(static_cast<size_t>(z) * kCells + y) * kCells + x] = 1;
  }
  auto isOccupied = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < kCells && y < kCells && z < kCells &&
           occupied[(static_cast<size_t>(z) * kCells + y) * kCells + x] != 0;
  };
  for (int z = 0; z < kCells; ++z)
    for (int y = 0; y < kCells; ++y)
      for (int x = 0; x < kCells; ++x) {
        if (!isOccupied(x, y, z)) continue;
        // A cell whose six face neighbours are all occupied adds nothing to the union of their
        // projections (with the eye outside it, the ray to any of its points enters it through
        // a face, which the neighbour across it holds; with the eye inside it, a corner behind
        // the eye is a neighbour's corner too, which gives the whole target as before).
        if (isOccupied(x - 1, y, z) && isOccupied(x + 1, y, z) && isOccupied(x, y - 1, z) &&
            isOccupied(x, y + 1, z) && isOccupied(x, y, z - 1) && isOccupied(x, y, z + 1))
          continue;
        lower_.push_back(lo + glm::vec3(x, y, z) * cellSize_);
        cells_.emplace_back(x, y, z);
      }
  origin_ = lo;
}

namespace {

// One axis of the projection: the products of mvp's column for the axis with each cell's low and
// high coordinate on it, for clip x, y and w (z is not needed) -- as projectBox (screen_rect.h)
// forms them: glm computes mvp * vec4(p, 1) as (c0 * p.x + c1 * p.y) + (c2 * p.z + c3), c being
// mvp's columns, and the grid's cells take only 2 x kCells coordinates per axis, so each product
// is formed once per frame instead of once per corner of every cell.
struct AxisTerms {
  // [cell][0: low, 1: high] of clip x, y, w.
  float x[OccupancyGrid::kCells][2], y[OccupancyGrid::kCells][2], w[OccupancyGrid::kCells][2];
};

AxisTerms axisTerms(const glm::vec4& column, float origin, float cellSize, const glm::vec4* add) {
  AxisTerms t;
  for (int i = 0; i < OccupancyGrid::kCells; ++i) {
    // The cell's coordinates as OccupancyGrid stores them: lower = origin + i * size, upper = lower + size.
    const float lo = origin + static_cast<float>(i) * cellSize, hi = lo + cellSize;
    const glm::vec4 a = add ? column * lo + *add : column * lo, b = add ? column * hi + *add : column * hi;
    t.x[i][0] = a.x, t.y[i][0] = a.y, t.w[i][0] = a.w;
    t.x[i][1] = b.x, t.y[i][1] = b.y, t.w[i][1] = b.w;
  }
  return t;
}

#if defined(__SSE2__)
// The same terms laid out for a cell's corners in four lanes (corner i: x's low or high term by
// bit 0 of i, y's by bit 1, z's by bit 2 -- lanes 0-3 the low z, 4-7 the high): one load each.
struct CornerLanes {
  // [cell] of clip x, y, w: x's terms as (lo, hi, lo, hi), y's as (lo, lo, hi, hi).
  __m128 x[OccupancyGrid::kCells][3], y[OccupancyGrid::kCells][3];
  // [cell][0: low, 1: high] of clip x, y, w, each in all four lanes.
  __m128 z[OccupancyGrid::kCells][2][3];
};

void fillCornerLanes(const AxisTerms& ax, const AxisTerms& ay, const AxisTerms& az, CornerLanes& l) {
  for (int i = 0; i < OccupancyGrid::kCells; ++i) {
    const float(*xs[3])[2] = {ax.x, ax.y, ax.w}, (*ys[3])[2] = {ay.x, ay.y, ay.w}, (*zs[3])[2] = {az.x, az.y, az.w};
    for (int k = 0; k < 3; ++k) {
      l.x[i][k] = _mm_setr_ps(xs[k][i][0], xs[k][i][1], xs[k][i][0], xs[k][i][1]);
      l.y[i][k] = _mm_setr_ps(ys[k][i][0], ys[k][i][0], ys[k][i][1], ys[k][i][1]);
      l.z[i][0][k] = _mm_set1_ps(zs[k][i][0]);
      l.z[i][1][k] = _mm_set1_ps(zs[k][i][1]);
    }
  }
}
#endif

// projectBox of one cell, bit for bit: the same additions in the same order, the same division,
// scale and offset per corner (IEEE operations: a vector lane rounds as the scalar does).
#if defined(__SSE2__)
bool projectCell(const CornerLanes& lanes, glm::u8vec3 cell, const glm::vec2& size, glm::vec2& min, glm::vec2& max) {
#else
bool projectCell(const AxisTerms& ax, const AxisTerms& ay, const AxisTerms& az, glm::u8vec3 cell,
                 const glm::vec2& size, glm::vec2& min, glm::vec2& max) {
#endif
#if defined(__SSE2__)
  // Corners 0-3 (low z) and 4-7 (high z) in four lanes each (CornerLanes).
  const int x = cell.x, y = cell.y, z = cell.z;
  const __m128 xyx = _mm_add_ps(lanes.x[x][0], lanes.y[y][0]);
  const __m128 xyy = _mm_add_ps(lanes.x[x][1], lanes.y[y][1]);
  const __m128 xyw = _mm_add_ps(lanes.x[x][2], lanes.y[y][2]);
  __m128 px[2], py[2];
  const __m128 half = _mm_set1_ps(0.5f), eps = _mm_set1_ps(1e-6f);
  const __m128 sizeX = _mm_set1_ps(size.x), sizeY = _mm_set1_ps(size.y);
  for (int c = 0; c < 2; ++c) {
    const __m128 cx = _mm_add_ps(xyx, lanes.z[z][c][0]);
    const __m128 cy = _mm_add_ps(xyy, lanes.z[z][c][1]);
    const __m128 cw = _mm_add_ps(xyw, lanes.z[z][c][2]);
    if (_mm_movemask_ps(_mm_cmpgt_ps(cw, eps)) != 0xF) return false;  // behind (or on) the eye plane
    px[c] = _mm_mul_ps(_mm_add_ps(_mm_mul_ps(_mm_div_ps(cx, cw), half), half), sizeX);
    py[c] = _mm_mul_ps(_mm_add_ps(_mm_mul_ps(_mm_div_ps(cy, cw), half), half), sizeY);
  }
  // The corners are finite (w > 1e-6): the extremes do not depend on the order they are taken in.
  alignas(16) float lo[8], hi[8];
  _mm_store_ps(lo, _mm_min_ps(px[0], px[1]));
  _mm_store_ps(lo + 4, _mm_min_ps(py[0], py[1]));
  _mm_store_ps(hi, _mm_max_ps(px[0], px[1]));
  _mm_store_ps(hi + 4, _mm_max_ps(py[0], py[1]));
  min = glm::vec2(std::min(std::min(lo[0], lo[1]), std::min(lo[2], lo[3])),
                  std::min(std::min(lo[4], lo[5]), std::min(lo[6], lo[7])));
  max = glm::vec2(std::max(std::max(hi[0], hi[1]), std::max(hi[2], hi[3])),
                  std::max(std::max(hi[4], hi[5]), std::max(hi[6], hi[7])));
  return true;
#else
  float cx[8], cy[8], cw[8];
  for (int i = 0; i < 8; ++i) {
    const int a = i & 1, b = (i >> 1) & 1, c = (i >> 2) & 1;
    cx[i] = (ax.x[cell.x][a] + ay.x[cell.y][b]) + az.x[cell.z][c];
    cy[i] = (ax.y[cell.x][a] + ay.y[cell.y][b]) + az.y[cell.z][c];
    cw[i] = (ax.w[cell.x][a] + ay.w[cell.y][b]) + az.w[cell.z][c];
    if (!(cw[i] > 1e-6f)) return false;  // behind (or on) the eye plane: no finite box
  }
  min = glm::vec2(1e30f);
  max = glm::vec2(-1e30f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec2 p((cx[i] / cw[i] * 0.5f + 0.5f) * size.x, (cy[i] / cw[i] * 0.5f + 0.5f) * size.y);
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  return true;
#endif
}

}  // namespace

std::vector<ScreenRect> coveredSpans(const OccupancyGrid& grid, const glm::mat4& mvp, int width, int height,
                                     int marginPx) {
  if (width <= 0 || height <= 0) return {};
  const int tilesX = (width + kScreenTile - 1) / kScreenTile, tilesY = (height + kScreenTile - 1) / kScreenTile;
  std::vector<uint8_t> marked(static_cast<size_t>(tilesX) * tilesY, 0);
  const glm::vec2 size(width, height);
  const glm::vec3 origin = grid.origin(), cellSize = grid.cellSize();
  const AxisTerms ax = axisTerms(mvp[0], origin.x, cellSize.x, nullptr);
  const AxisTerms ay = axisTerms(mvp[1], origin.y, cellSize.y, nullptr);
  const AxisTerms az = axisTerms(mvp[2], origin.z, cellSize.z, &mvp[3]);
#if defined(__SSE2__)
  CornerLanes lanes;
  fillCornerLanes(ax, ay, az, lanes);
#endif
  const float m = static_cast<float>(marginPx);
  for (const glm::u8vec3 cell : grid.cells()) {
    glm::vec2 min, max;
#if defined(__SSE2__)
    if (!projectCell(lanes, cell, size, min, max)) return {{0, 0, width, height}};
#else
    if (!projectCell(ax, ay, az, cell, size, min, max)) return {{0, 0, width, height}};
#endif
    if (max.x + m < 0.0f || max.y + m < 0.0f || min.x - m >= static_cast<float>(width) ||
        min.y - m >= static_cast<float>(height))
      continue;  // off screen
    const int tx0 = std::clamp(static_cast<int>(std::floor((min.x - m) / kScreenTile)), 0, tilesX - 1);
    const int ty0 = std::clamp(static_cast<int>(std::floor((min.y - m) / kScreenTile)), 0, tilesY - 1);
    const int tx1 = std::clamp(static_cast<int>(std::floor((max.x + m) / kScreenTile)), 0, tilesX - 1);
    const int ty1 = std::clamp(static_cast<int>(std::floor((max.y + m) / kScreenTile)), 0, tilesY - 1);
    // A few tiles per row: marked in place (|=, which the compiler keeps a loop, not a memset call).
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) marked[static_cast<size_t>(ty) * tilesX + tx] |= 1;
  }
  // Each row's runs of marked tiles; a run that the row below had too (same first and last tile)
  // grows the rectangle that run started instead of starting one.
  std::vector<ScreenRect> spans;
  std::vector<std::pair<int, size_t>> open, stillOpen;  // (first tile of a run, its rectangle) in the row below
  for (int ty = 0; ty < tilesY; ++ty) {
    stillOpen.clear();
    size_t below = 0;
    for (int tx = 0; tx < tilesX;) {
      if (!marked[static_cast<size_t>(ty) * tilesX + tx]) {
        ++tx;
        continue;
      }
      const int start = tx;
      while (tx < tilesX && marked[static_cast<size_t>(ty) * tilesX + tx]) ++tx;
      const int x0 = start * kScreenTile, y0 = ty * kScreenTile;
      const int x1 = std::min(tx * kScreenTile, width), y1 = std::min(y0 + kScreenTile, height);
      while (below < open.size() && open[below].first < start) ++below;
      if (below < open.size() && open[below].first == start && spans[open[below].second].width == x1 - x0) {
        ScreenRect& r = spans[open[below].second];
        r.height = y1 - r.y;
        stillOpen.emplace_back(start, open[below].second);
      } else {
        spans.push_back({x0, y0, x1 - x0, y1 - y0});
        stillOpen.emplace_back(start, spans.size() - 1);
      }
    }
    open.swap(stillOpen);
  }
  return spans;
}

}  // namespace marble
