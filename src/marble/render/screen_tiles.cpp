#include "marble/render/screen_tiles.h"

#include <algorithm>
#include <cmath>

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
      }
}

namespace {

// projectBox (screen_rect.h) of one cell, bit for bit, with a third of its multiplications: glm
// computes mvp * vec4(p, 1) as (c0 * p.x + c1 * p.y) + (c2 * p.z + c3) (c = mvp's columns), and
// the cell's eight corners take only two values per axis, so each product is formed once.
bool projectCell(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& mvp, const glm::vec2& size, glm::vec2& min,
                 glm::vec2& max) {
  const glm::vec4 xs[2] = {mvp[0] * lo.x, mvp[0] * hi.x}, ys[2] = {mvp[1] * lo.y, mvp[1] * hi.y};
  const glm::vec4 zs[2] = {mvp[2] * lo.z + mvp[3], mvp[2] * hi.z + mvp[3]};
  min = glm::vec2(1e30f);
  max = glm::vec2(-1e30f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 clip = (xs[i & 1] + ys[(i >> 1) & 1]) + zs[(i >> 2) & 1];
    if (!(clip.w > 1e-6f)) return false;  // behind (or on) the eye plane: no finite box
    const glm::vec2 p = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  return true;
}

}  // namespace

std::vector<ScreenRect> coveredSpans(const OccupancyGrid& grid, const glm::mat4& mvp, int width, int height,
                                     int marginPx) {
  if (width <= 0 || height <= 0) return {};
  const int tilesX = (width + kScreenTile - 1) / kScreenTile, tilesY = (height + kScreenTile - 1) / kScreenTile;
  std::vector<uint8_t> marked(static_cast<size_t>(tilesX) * tilesY, 0);
  const glm::vec2 size(width, height);
  for (const glm::vec3& lower : grid.lowerCorners()) {
    glm::vec2 min, max;
    if (!projectCell(lower, lower + grid.cellSize(), mvp, size, min, max)) return {{0, 0, width, height}};
    const float m = static_cast<float>(marginPx);
    if (max.x + m < 0.0f || max.y + m < 0.0f || min.x - m >= static_cast<float>(width) ||
        min.y - m >= static_cast<float>(height))
      continue;  // off screen
    const int tx0 = std::clamp(static_cast<int>(std::floor((min.x - m) / kScreenTile)), 0, tilesX - 1);
    const int ty0 = std::clamp(static_cast<int>(std::floor((min.y - m) / kScreenTile)), 0, tilesY - 1);
    const int tx1 = std::clamp(static_cast<int>(std::floor((max.x + m) / kScreenTile)), 0, tilesX - 1);
    const int ty1 = std::clamp(static_cast<int>(std::floor((max.y + m) / kScreenTile)), 0, tilesY - 1);
    for (int ty = ty0; ty <= ty1; ++ty)
      std::fill(marked.begin() + ty * tilesX + tx0, marked.begin() + ty * tilesX + tx1 + 1, uint8_t{1});
  }
  std::vector<ScreenRect> spans;
  for (int ty = 0; ty < tilesY; ++ty)
    for (int tx = 0; tx < tilesX;) {
      if (!marked[static_cast<size_t>(ty) * tilesX + tx]) {
        ++tx;
        continue;
      }
      const int start = tx;
      while (tx < tilesX && marked[static_cast<size_t>(ty) * tilesX + tx]) ++tx;
      const int x0 = start * kScreenTile, y0 = ty * kScreenTile;
      spans.push_back({x0, y0, std::min(tx * kScreenTile, width) - x0, std::min(y0 + kScreenTile, height) - y0});
    }
  return spans;
}

}  // namespace marble
