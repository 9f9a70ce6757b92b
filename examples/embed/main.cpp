// Embedding marble: a stone drawn into a framebuffer this program owns, then its texture set
// baked, all through the public interface marble/marble.h.
//
//   marble_embed_example OUT_DIR [INPUT]
//
// writes OUT_DIR/render.ppm (the frame read back from our framebuffer) and OUT_DIR/textures/
// (what `marble bake` writes). Exit 0 when the picture shows the stone and the set is complete.
#include <epoxy/gl.h>  // marble::marble brings libepoxy; any GL loader works for your own calls

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "marble/marble.h"

namespace {

constexpr int kWidth = 160, kHeight = 120;

// Our own framebuffer: one RGBA8 colour renderbuffer (marble needs no depth from the caller).
struct Framebuffer {
  GLuint fbo = 0, color = 0;
  Framebuffer() {
    glCreateRenderbuffers(1, &color);
    glNamedRenderbufferStorage(color, GL_RGBA8, kWidth, kHeight);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferRenderbuffer(fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  }
  ~Framebuffer() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &color);
  }
  std::vector<unsigned char> read() const {  // RGBA, bottom row first (OpenGL's order)
    std::vector<unsigned char> pixels(static_cast<size_t>(kWidth) * kHeight * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
  }
};

void writePpm(const std::filesystem::path& path, const std::vector<unsigned char>& rgba) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << kWidth << " " << kHeight << "\n255\n";
  for (int y = kHeight - 1; y >= 0; --y)
    for (int x = 0; x < kWidth; ++x) out.write(reinterpret_cast<const char*>(&rgba[(static_cast<size_t>(y) * kWidth + x) * 4]), 3);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR [INPUT]\n", argv[0]);
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  try {
    marble::api::Stone stone({.input = argc > 2 ? argv[2] : "builtin:sphere", .preset = "carrara", .sets = {}, .up = ""});

    marble::api::OffscreenContext context;  // a windowed program uses its own context instead
    std::printf("GL: %s\n", context.renderer().c_str());
    Framebuffer target;
    marble::api::StoneRenderer renderer(stone);
    renderer.render(target.fbo, kWidth, kHeight);
    const std::vector<unsigned char> pixels = target.read();
    writePpm(out / "render.ppm", pixels);
    // The stone is in the middle of the default view: its centre differs from the corner (background).
    const auto at = [&](int x, int y) { return &pixels[(static_cast<size_t>(y) * kWidth + x) * 4]; };
    const unsigned char *centre = at(kWidth / 2, kHeight / 2), *corner = at(0, 0);
    int difference = 0;
    for (int c = 0; c < 3; ++c) difference += std::abs(centre[c] - corner[c]);
    std::printf("rendered %zu triangles into framebuffer %u: centre (%d, %d, %d), corner (%d, %d, %d)\n", stone.triangleCount(),
                target.fbo, centre[0], centre[1], centre[2], corner[0], corner[1], corner[2]);
    if (difference < 30) {
      std::fprintf(stderr, "the frame does not show the stone\n");
      return 1;
    }

    const marble::api::BakeSummary baked = marble::api::bakeTextureSet(stone, out / "textures", {.size = 64, .supersample = 1});
    std::printf("baked %dx%d (thickness %dx%d, 1.0 = %.3g mm), %s texture coordinates\n", baked.size, baked.size,
                baked.thicknessSize, baked.thicknessSize, baked.thicknessScaleMm, baked.unwrapped ? "unwrapped" : "the file's");
    for (const char* file : {"base_color.png", "metallic_roughness.png", "thickness.png", "material.json"})
      if (!std::filesystem::exists(out / "textures" / file)) {
        std::fprintf(stderr, "missing %s\n", file);
        return 1;
      }
  } catch (const marble::api::InputError& e) {
    std::fprintf(stderr, "bad input: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
