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
  for (int z = 0; z < kCells; ++z)
    for (int y = 0; y < kCells; ++y)
      for (int x = 0; x < kCells; ++x)
        if (occupied[(static_cast<size_t>(z) * kCells + y) * kCells + x])
          lower_.push_back(lo + glm::vec3(x, y, z) * cellSize_);
}

std::vector<ScreenRect> coveredSpans(const OccupancyGrid& grid, const glm::mat4& mvp, int width, int height,
                                     int marginPx) {
  if (width <= 0 || height <= 0) return {};
  const int tilesX = (width + kScreenTile - 1) / kScreenTile, tilesY = (height + kScreenTile - 1) / kScreenTile;
  std::vector<uint8_t> marked(static_cast<size_t>(tilesX) * tilesY, 0);
  for (const glm::vec3& lower : grid.lowerCorners()) {
    glm::vec2 min, max;
    if (!projectBox(lower, lower + grid.cellSize(), mvp, width, height, min, max)) return {{0, 0, width, height}};
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
