// The spans FXAA draws (src/marble/render/screen_tiles.h): every pixel a mesh covers, with its
// neighbours, lies in one; on a mesh that leaves much of its bounding rectangle empty they cover
// less than the rectangle; a cell behind the camera gives the whole target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_support.h"
#include "marble/mesh/mesh.h"
#include "marble/render/screen_tiles.h"
#include "marble/render/view_setup.h"

using namespace marble;
using namespace marble::test;

namespace {

bool inSpans(const std::vector<ScreenRect>& spans, int x, int y) {
  for (const ScreenRect& r : spans)
    if (x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height) return true;
  return false;
}

}  // namespace

TEST(ScreenTiles, EveryCoveredPixelAndItsNeighboursLieInASpan) {
  HeadlessContext& context = glContext();
  (void)context;
  for (const char* name : {"sculpture", "torus", "slab", "sphere"}) {
    const Mesh mesh = builtinMesh(name);
    Renderer renderer;
    renderer.setMesh(mesh);
    Scene s;
    s.render.width = 200;
    s.render.height = 150;
    s.render.mode = RenderMode::Normal;  // every covered pixel differs from the background
    s.render.antialias = Antialias::None;
    s.camera.position = glm::vec3(1.3f, 0.9f, 2.4f);
    const ImageRGBA8 img = renderImage(renderer, s);
    const std::vector<ScreenRect> spans =
        coveredSpans(OccupancyGrid(mesh), cameraMatrices(s.camera, 200.0f / 150.0f).viewProj, 200, 150, 2);
    const glm::u8vec4 bg = img.at(0, 0);
    int covered = 0, spanArea = 0;
    for (const ScreenRect& r : spans) spanArea += r.width * r.height;
    for (int y = 0; y < 150; ++y)
      for (int x = 0; x < 200; ++x) {
        if (img.at(x, y) == bg) continue;
        ++covered;
        const int glY = 149 - y;  // the image's rows run top down, the spans' bottom up
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = glY + dy;
            if (nx < 0 || ny < 0 || nx >= 200 || ny >= 150) continue;
            ASSERT_TRUE(inSpans(spans, nx, ny)) << name << ": pixel " << nx << "," << ny;
          }
      }
    EXPECT_GT(covered, 1000) << name;
    EXPECT_LT(spanArea, 200 * 150) << name << ": not the whole frame";
  }
}

TEST(ScreenTiles, ATorusLeavesItsHoleOut) {
  const Mesh mesh = builtinMesh("torus");
  Camera camera;
  // Straight down the axis, close: the hole (radius 0.43 of 1) about 130 pixels across the middle.
  camera.position = glm::vec3(0.0f, 3.0f, 0.01f);
  camera.fov_y_deg = 30.0f;
  const std::vector<ScreenRect> spans = coveredSpans(OccupancyGrid(mesh), cameraMatrices(camera, 1.0f).viewProj, 512, 512, 2);
  EXPECT_FALSE(inSpans(spans, 256, 256)) << "the centre of the hole";
  EXPECT_TRUE(inSpans(spans, 256, 256 + 200)) << "the ring";
}

TEST(ScreenTiles, ACellBehindTheCameraGivesTheWholeTarget) {
  const Mesh mesh = builtinMesh("sphere");
  Camera inside;
  inside.position = glm::vec3(0.0f, 0.0f, 0.2f);  // within the mesh's box
  const std::vector<ScreenRect> spans = coveredSpans(OccupancyGrid(mesh), cameraMatrices(inside, 1.0f).viewProj, 64, 48, 2);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0], (ScreenRect{0, 0, 64, 48}));
}

TEST(ScreenTiles, AnEmptyMeshHasNoCells) {
  EXPECT_TRUE(OccupancyGrid(Mesh{}).lowerCorners().empty());
  EXPECT_TRUE(coveredSpans(OccupancyGrid(Mesh{}), glm::mat4(1.0f), 64, 64, 2).empty());
}

TEST(ScreenTiles, CellsInsideTheOccupiedRegionAreLeftOut) {
  // One triangle across the unit cube's diagonal: its bounding box is the whole grid, so every
  // cell is occupied and only the grid's outer layer has an empty face neighbour.
  Mesh mesh;
  mesh.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 1.0f}, {1.0f, 0.0f, 1.0f}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  const int n = OccupancyGrid::kCells;
  EXPECT_EQ(OccupancyGrid(mesh).lowerCorners().size(), static_cast<size_t>(n * n * n - (n - 2) * (n - 2) * (n - 2)));
}

TEST(ScreenTiles, SpansAreThoseOfEveryCellsProjectedBox) {
  // coveredSpans projects a cell's corners with its own arithmetic; the tiles must be those of
  // projectBox (screen_rect.h) over the same cells, bit for bit, from near and far.
  const Mesh mesh = builtinMesh("sculpture");
  const OccupancyGrid grid(mesh);
  for (const glm::vec3 eye : {glm::vec3(1.3f, 0.9f, 2.4f), glm::vec3(-0.4f, 0.3f, 1.6f), glm::vec3(0.0f, 5.0f, 0.5f)}) {
    Camera camera;
    camera.position = eye;
    const glm::mat4 mvp = cameraMatrices(camera, 640.0f / 480.0f).viewProj;
    std::vector<uint8_t> marked(40 * 30, 0);
    for (const glm::vec3& lower : grid.lowerCorners()) {
      glm::vec2 lo, hi;
      ASSERT_TRUE(projectBox(lower, lower + grid.cellSize(), mvp, 640, 480, lo, hi));
      for (int ty = std::clamp(static_cast<int>(std::floor((lo.y - 2.0f) / 16.0f)), 0, 29);
           ty <= std::clamp(static_cast<int>(std::floor((hi.y + 2.0f) / 16.0f)), 0, 29); ++ty)
        for (int tx = std::clamp(static_cast<int>(std::floor((lo.x - 2.0f) / 16.0f)), 0, 39);
             tx <= std::clamp(static_cast<int>(std::floor((hi.x + 2.0f) / 16.0f)), 0, 39); ++tx)
          if (hi.x + 2.0f >= 0.0f && hi.y + 2.0f >= 0.0f && lo.x - 2.0f < 640.0f && lo.y - 2.0f < 480.0f)
            marked[ty * 40 + tx] = 1;
    }
    std::vector<uint8_t> fromSpans(40 * 30, 0);
    for (const ScreenRect& r : coveredSpans(grid, mvp, 640, 480, 2))
      for (int y = r.y; y < r.y + r.height; y += 16)
        for (int x = r.x; x < r.x + r.width; x += 16) fromSpans[(y / 16) * 40 + x / 16] = 1;
    EXPECT_EQ(fromSpans, marked) << "eye " << eye.x << "," << eye.y << "," << eye.z;
  }
}

TEST(ScreenTiles, CellIndicesGiveTheStoredCornersBitForBit) {
  // coveredSpans forms the corners from the indices (per-axis tables): they must be the stored ones.
  const OccupancyGrid grid(builtinMesh("sculpture"));
  ASSERT_EQ(grid.cells().size(), grid.lowerCorners().size());
  for (size_t i = 0; i < grid.cells().size(); ++i) {
    const glm::vec3 fromIndex = grid.origin() + glm::vec3(grid.cells()[i]) * grid.cellSize();
    ASSERT_EQ(std::memcmp(&fromIndex, &grid.lowerCorners()[i], sizeof(fromIndex)), 0) << "cell " << i;
  }
}

TEST(ScreenTiles, SpansAreDisjointAndRowsWithTheSameRunShareOne) {
  // The rows' runs are merged upwards: no pixel lies in two spans (FXAA would filter it twice),
  // and a run repeated in the row above does not start a span of its own.
  const Mesh mesh = builtinMesh("sphere");
  Camera camera;
  camera.position = glm::vec3(0.0f, 0.0f, 3.0f);
  const std::vector<ScreenRect> spans = coveredSpans(OccupancyGrid(mesh), cameraMatrices(camera, 1.0f).viewProj, 320, 320, 2);
  std::vector<int> hits(320 * 320, 0);
  for (const ScreenRect& r : spans)
    for (int y = r.y; y < r.y + r.height; ++y)
      for (int x = r.x; x < r.x + r.width; ++x) ++hits[y * 320 + x];
  EXPECT_EQ(*std::max_element(hits.begin(), hits.end()), 1);
  int rowsCovered = 0;
  for (int ty = 0; ty < 20; ++ty) rowsCovered += hits[(ty * 16) * 320 + 160] > 0 ? 1 : 0;
  ASSERT_GT(rowsCovered, 3);
  int spansOnCentre = 0;  // the sphere's middle column of tiles: its rows' runs differ, but some repeat
  for (const ScreenRect& r : spans) spansOnCentre += r.x <= 160 && 160 < r.x + r.width ? 1 : 0;
  EXPECT_LT(spansOnCentre, rowsCovered) << "a run repeated in the row above starts no span";
}
