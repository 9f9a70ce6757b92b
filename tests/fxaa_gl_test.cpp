// FXAA (src/marble/render/fxaa_pass.h) on synthetic pictures: a hard straight edge between
// black and white, at several slopes. Flat regions must come out bit for bit; pixels on the edge
// must take intermediate values that follow the true edge better than the staircase did.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

#include "gl_support.h"
#include "marble/render/fxaa_pass.h"
#include "marble/render/post_pass.h"

using namespace marble;
using namespace marble::test;

namespace {

constexpr int kWidth = 96, kHeight = 64;

// A straight edge near the picture's centre at `angleDeg` from the x axis; white above it.
struct Edge {
  double angleDeg;
  double maxErrorRatio;  // how much of the staircase's error against the true coverage may remain
  // > 0 above the edge (white), < 0 below, in pixel units (x right, y up, GL's row order).
  double side(double x, double y) const {
    const double a = angleDeg * M_PI / 180.0;
    return -(x - kWidth / 2.0 - 0.3) * std::sin(a) + (y - kHeight / 2.0 - 0.2) * std::cos(a);
  }
  // The aliased picture: each pixel takes the colour at its centre.
  uint8_t aliased(int x, int y) const { return side(x + 0.5, y + 0.5) > 0 ? 255 : 0; }
  // The white fraction of the pixel's area (16 x 16 samples).
  double coverage(int x, int y) const {
    int white = 0;
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) white += side(x + (i + 0.5) / 16.0, y + (j + 0.5) / 16.0) > 0;
    return white / 256.0;
  }
};

void PrintTo(const Edge& e, std::ostream* os) { *os << e.angleDeg << " degrees"; }

// The display image's alpha as the post pass writes it for FXAA: the colour's luma.
uint8_t lumaByte(const uint8_t* rgb) {
  const float l = fxaaLuma(glm::vec3(rgb[0], rgb[1], rgb[2]) / 255.0f);
  return static_cast<uint8_t>(std::lround(std::clamp(l, 0.0f, 1.0f) * 255.0f));
}

// GL's row order (row 0 at the bottom) throughout; grey values, RGBA8, luma in alpha.
std::vector<uint8_t> edgeImage(const Edge& e) {
  std::vector<uint8_t> px(static_cast<size_t>(kWidth) * kHeight * 4);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      uint8_t* p = &px[(static_cast<size_t>(y) * kWidth + x) * 4];
      p[0] = p[1] = p[2] = e.aliased(x, y);
      p[3] = lumaByte(p);
    }
  return px;
}

// The colour channels alone (FXAA's output is opaque; its input carries luma in alpha).
std::vector<uint8_t> rgbOf(const std::vector<uint8_t>& rgba) {
  std::vector<uint8_t> rgb;
  for (size_t i = 0; i < rgba.size(); i += 4) rgb.insert(rgb.end(), rgba.begin() + static_cast<ptrdiff_t>(i),
                                                         rgba.begin() + static_cast<ptrdiff_t>(i + 3));
  return rgb;
}

struct FxaaFixture : ::testing::Test {
  HeadlessContext& context = glContext();  // before any GL object
  FxaaPass pass{ShaderLibrary()};

  // The pass as the renderer runs it, leaving no program current (Renderer::render holds a
  // gl::NoProgramCurrentOnExit): the textures handed to it go next, and a program left current
  // with an empty unit is what NVIDIA's driver reports at the next clear.
  void runPass(GLuint image, GLuint fbo, int width, int height, const std::vector<ScreenRect>& spans,
               const glm::vec3& background) {
    const gl::NoProgramCurrentOnExit noProgramAfter;
    pass.run(image, fbo, width, height, spans, background);
  }

  // Runs FXAA over `rgba` (GL row order) and returns the result in the same order.
  std::vector<uint8_t> run(const std::vector<uint8_t>& rgba) {
    const gl::Texture input = gl::makeTexture2D(GL_RGBA8, kWidth, kHeight, GL_LINEAR);
    glTextureSubImage2D(input.id(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    OffscreenTarget target(kWidth, kHeight);
    runPass(input.id(), target.fbo(), kWidth, kHeight, {ScreenRect{0, 0, kWidth, kHeight}}, glm::vec3(0.0f));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    ImageRGBA8 out = target.read();
    flipRows(out);  // back to GL's order
    return out.pixels;
  }
};

uint8_t grey(const std::vector<uint8_t>& px, int x, int y) { return px[(static_cast<size_t>(y) * kWidth + x) * 4]; }

// Whether the aliased picture is one colour over the pixel's 3 x 3 neighbourhood.
bool flatAround(const Edge& e, int x, int y) {
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const int xi = std::clamp(x + i, 0, kWidth - 1), yj = std::clamp(y + j, 0, kHeight - 1);
      if (e.aliased(xi, yj) != e.aliased(x, y)) return false;
    }
  return true;
}

class FxaaEdge : public FxaaFixture, public ::testing::WithParamInterface<Edge> {};

}  // namespace

TEST_P(FxaaEdge, SmoothsTheStaircaseAndLeavesFlatRegionsExactlyAlone) {
  const Edge edge = GetParam();
  const std::vector<uint8_t> in = edgeImage(edge);
  const std::vector<uint8_t> out = run(in);
  int flat = 0, flatChanged = 0, onEdge = 0, intermediate = 0;
  double errorBefore = 0, errorAfter = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(out[(static_cast<size_t>(y) * kWidth + x) * 4 + c], grey(out, x, y)) << "grey stays grey";
      if (flatAround(edge, x, y)) {
        ++flat;
        flatChanged += grey(out, x, y) != grey(in, x, y);
        continue;
      }
      // Next to the edge: how far each picture is from the pixel's true coverage. FXAA blends
      // the display values, so coverage is compared with them directly (0 black ... 1 white).
      const double truth = edge.coverage(x, y);
      if (truth == 0.0 || truth == 1.0) continue;  // the edge only grazes the neighbourhood
      ++onEdge;
      intermediate += grey(out, x, y) > 0 && grey(out, x, y) < 255;
      errorBefore += std::abs(grey(in, x, y) / 255.0 - truth);
      errorAfter += std::abs(grey(out, x, y) / 255.0 - truth);
    }
  EXPECT_GT(flat, kWidth * kHeight / 2);
  EXPECT_EQ(flatChanged, 0) << "pixels with a flat 3x3 neighbourhood must be returned bit for bit";
  ASSERT_GT(onEdge, 0);
  EXPECT_GT(intermediate, onEdge / 2) << "most pixels the edge crosses get an intermediate value";
  EXPECT_LE(errorAfter, edge.maxErrorRatio * errorBefore) << "mean error against the true coverage: " << errorBefore / onEdge
                                           << " aliased, " << errorAfter / onEdge << " after FXAA";
}

// Shallow and steep (the long staircases the edge search exists for), nearly axis-aligned, and
// both diagonals. FXAA only sees the staircase: at 45 degrees it is the same for every line
// within half a pixel of it, so where the line nearly meets the pixel centres (45, not 135 here)
// the true coverage cannot be recovered; there the blend must only not make things worse.
INSTANTIATE_TEST_SUITE_P(Angles, FxaaEdge,
                         ::testing::Values(Edge{8, 0.3}, Edge{20, 0.5}, Edge{70, 0.5}, Edge{160, 0.5}, Edge{86, 0.4},
                                           Edge{135, 0.4}, Edge{45, 1.0}),
                         [](const auto& info) { return "deg" + std::to_string(static_cast<int>(info.param.angleDeg)); });

TEST_F(FxaaFixture, AFlatPictureAndASoftGradientAreUnchanged) {
  std::vector<uint8_t> px(static_cast<size_t>(kWidth) * kHeight * 4);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      uint8_t* p = &px[(static_cast<size_t>(y) * kWidth + x) * 4];
      p[0] = static_cast<uint8_t>(40 + x);  // one step per pixel: far below the contrast threshold
      p[1] = static_cast<uint8_t>(90 + y / 2);
      p[2] = 200;
      p[3] = lumaByte(p);
    }
  const std::vector<uint8_t> out = run(px);
  EXPECT_EQ(rgbOf(out), rgbOf(px));
  for (size_t i = 3; i < out.size(); i += 4) ASSERT_EQ(out[i], 255) << "opaque";
}

// The renderer filters only spans around the object, outside which the picture is background:
// inside, the result is the whole-frame filter's; outside, the background, opaque.
TEST_F(FxaaFixture, SpansAreFilteredAsInTheWholeFrameAndTheRestIsBackground) {
  const std::vector<uint8_t> px = edgeImage(Edge{30.0, 1.0});
  const std::vector<uint8_t> whole = run(px);
  OffscreenTarget display(kWidth, kHeight), target(kWidth, kHeight);
  glTextureSubImage2D(display.texture(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  // Two spans, as the renderer's rows of tiles: [20, 60) x [10, 25) and [28, 44) x [25, 40).
  const std::vector<ScreenRect> spans{{20, 10, 40, 15}, {28, 25, 16, 15}};
  const glm::vec3 background(0.2f, 0.4f, 0.6f);
  runPass(display.texture(), target.fbo(), kWidth, kHeight, spans, background);
  ImageRGBA8 out = target.read();
  flipRows(out);
  int filteredInside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = (static_cast<size_t>(y) * kWidth + x) * 4;
      bool inside = false;
      for (const ScreenRect& r : spans) inside |= x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
      if (inside) {
        EXPECT_EQ(out.pixels[i], whole[i]) << x << "," << y << " inside";
        filteredInside += whole[i] != px[i];
      } else {
        EXPECT_EQ(out.pixels[i], 51) << x << "," << y << " outside";  // 0.2 x 255
        EXPECT_EQ(out.pixels[i + 2], 153);
      }
      EXPECT_EQ(out.pixels[i + 3], 255) << x << "," << y << " opaque";
    }
  EXPECT_GT(filteredInside, 10) << "the edge crosses the spans";
}

// In the renderer FXAA draws only the spans of screen tiles the mesh can cover: the picture
// must be exactly the one FXAA over the whole frame gives, for meshes of every kind.
TEST_F(FxaaFixture, TheRenderersSpansGiveTheWholeFramePicture) {
  for (const char* mesh : {"sculpture", "torus", "slab", "sphere"}) {
    Renderer renderer;
    renderer.setMesh(builtinMesh(mesh));
    Scene s;
    s.render.width = 160;
    s.render.height = 120;
    s.camera.position = glm::vec3(1.0f, 1.4f, 2.2f);  // close and from above: the object fills much of the frame
    const ImageRGBA8 spans = renderImage(renderer, s);
    OffscreenTarget whole(160, 120);
    runPass(renderer.displayImageTexture(), whole.fbo(), 160, 120, {ScreenRect{0, 0, 160, 120}},
             glm::clamp(s.render.background, 0.0f, 1.0f));
    EXPECT_EQ(spans.pixels, whole.read().pixels) << mesh;
  }
}
