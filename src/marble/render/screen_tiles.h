#pragma once
// Which parts of the screen a mesh can cover, finer than its bounding rectangle: the mesh is
// cut into a coarse grid of cells (object space, at load), and each frame the cells holding
// part of a triangle (but not those enclosed by six such cells) are projected; the 16x16-pixel
// tiles they touch, merged into rectangles (runs per row, a run repeated in the rows above
// merged with it), are where FXAA draws (on the dragon at 800x800,
// 69 % of the rectangle). Conservative: every pixel the mesh covers, and its neighbours, lie in
// a span; on llvmpipe a pixel outside every span costs nothing, where a branch on "is this
// background?" would cost the whole shader.
#include <cstdint>
#include <vector>

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/glm.hpp>

#include "marble/mesh/mesh.h"
#include "marble/render/screen_rect.h"

namespace marble {

class OccupancyGrid {
public:
  static constexpr int kCells = 32;  // per axis; a cell of the dragon at 800x800 spans about 17 pixels
  OccupancyGrid() = default;
  // Marks every cell that a triangle's bounding box overlaps (conservative).
  explicit OccupancyGrid(const Mesh& mesh);
  // The occupied cells' corners, less cells whose six face neighbours are all occupied (they
  // project inside their neighbours): cell i spans [lower[i], lower[i] + cellSize].
  const std::vector<glm::vec3>& lowerCorners() const { return lower_; }
  // The same cells by index (lower_[i] == origin() + glm::vec3(cells()[i]) * cellSize(), bit for
  // bit): a cell's corner coordinates take one of 2 x 32 values per axis.
  const std::vector<glm::u8vec3>& cells() const { return cells_; }
  glm::vec3 origin() const { return origin_; }
  glm::vec3 cellSize() const { return cellSize_; }

private:
  std::vector<glm::vec3> lower_;
  std::vector<glm::u8vec3> cells_;
  glm::vec3 origin_{0.0f};
  glm::vec3 cellSize_{0.0f};
};

constexpr int kScreenTile = 16;  // pixels

// Rectangles of whole tiles (clamped to the target) covering every tile that an occupied cell's
// projection, grown by `marginPx`, touches, and no other: each row's runs of such tiles, a run
// merged with the same run in the rows above it (fewer draws, the same pixels). Disjoint. The
// whole target when a cell reaches behind the camera.
std::vector<ScreenRect> coveredSpans(const OccupancyGrid& grid, const glm::mat4& mvp, int width, int height,
                                     int marginPx);

}  // namespace marble
