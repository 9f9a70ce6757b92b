// GL reuses object names (gl/borrowed.h): a texture deleted and a new one created can share a
// name, and a framebuffer that held the deleted one (unbound when it was deleted, OpenGL 4.5
// 9.2.8) keeps it alive and keeps showing it. Whoever is handed a texture must therefore attach
// it, not compare its name with the last one's.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <iostream>

#include "gl_support.h"
#include "marble/gl/handles.h"
#include "marble/render/offscreen_target.h"

namespace marble {
namespace {

using test::glContext;

// The colour at (0, 0) of `fbo`'s GL_COLOR_ATTACHMENT1.
std::array<uint8_t, 4> attachment1Pixel(GLuint fbo) {
  std::array<uint8_t, 4> p{};
  glNamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return p;
}

gl::Texture filled(uint8_t r, uint8_t g) {
  gl::Texture t = gl::makeTexture2D(GL_RGBA8, 4, 4, GL_NEAREST);
  const uint8_t c[4] = {r, g, 0, 255};
  glClearTexImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  return t;
}

TEST(BorrowedNames, ANewTextureWithAReusedNameIsAttachedNotSkipped) {
  // Mesa hands out fresh names unless told to reuse them, as other drivers do (read when the
  // context is made: ctest runs each test in a process of its own, where this one makes it).
  setenv("force_gl_names_reuse", "true", 0);
  glContext();
  OffscreenTarget target(4, 4);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the target's framebuffer is not bound when `red` goes
  gl::Texture red = filled(255, 0);
  const GLuint redName = red.id();
  target.attach(GL_COLOR_ATTACHMENT1, red.id());
  ASSERT_EQ(attachment1Pixel(target.fbo())[0], 255);
  red.reset();
  gl::Texture green = filled(0, 255);
  // The premise: the driver hands out the freed name again. Where it does not (a context made
  // earlier in the same process), the test still checks that the new texture is the one attached.
  if (green.id() != redName) std::cout << "[          ] the driver did not reuse the name this time\n";
  target.attach(GL_COLOR_ATTACHMENT1, green.id());
  const auto p = attachment1Pixel(target.fbo());
  EXPECT_EQ(p[0], 0) << "the framebuffer still shows the deleted texture that had the same name";
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(BorrowedNames, WithoutReattachingTheFramebufferKeepsTheDeletedTexture) {  // the negative control
  glContext();
  OffscreenTarget target(4, 4);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::Texture red = filled(255, 0);
  target.attach(GL_COLOR_ATTACHMENT1, red.id());
  red.reset();
  gl::Texture green = filled(0, 255);
  // What a name comparison did: "same name, nothing to do". The stale picture is what the test
  // above would catch.
  const auto p = attachment1Pixel(target.fbo());
  EXPECT_EQ(p[0], 255) << "a deleted texture attached to an unbound framebuffer stays alive";
  EXPECT_EQ(p[1], 0);
}

// The caller's loop (the viewer's, the benchmark's): draw only when the target does not hold
// the current frame; `shown` is the frame the target holds.
void present(Renderer& renderer, const Scene& scene, const OffscreenTarget& target, Renderer::FrameToken& shown) {
  if (!renderer.isCurrent(scene, glm::mat4(1.0f), shown, target.width(), target.height()))
    shown = renderer.render(scene, glm::mat4(1.0f), target.fbo(), target.width(), target.height());
}

// Renderer::isCurrent once compared the target framebuffer's name: a new target that got a
// deleted one's name counted as holding its frame, and stayed empty.
TEST(BorrowedNames, ANewTargetWithAReusedNameIsDrawnInto) {
  setenv("force_gl_names_reuse", "true", 0);
  glContext();
  Scene scene;
  scene.render.width = scene.render.height = 32;
  scene.render.mode = RenderMode::Marble;
  Renderer renderer;
  renderer.setMesh(builtinMesh("sphere"));
  Renderer::FrameToken shown;
  ImageRGBA8 first;
  GLuint oldName = 0;
  {
    OffscreenTarget target(32, 32);
    present(renderer, scene, target, shown);
    first = target.read();
    oldName = target.fbo();
  }  // deleted, as the viewer remakes its view image
  OffscreenTarget target(32, 32);
  shown = {};  // a new target holds no frame
  if (target.fbo() != oldName) std::cout << "[          ] the driver did not reuse the name this time\n";
  const float magenta[4] = {1.0f, 0.0f, 1.0f, 1.0f};  // what the target shows if nothing is drawn
  glClearNamedFramebufferfv(target.fbo(), GL_COLOR, 0, magenta);
  const ImageRGBA8 undrawn = target.read();
  present(renderer, scene, target, shown);
  const ImageRGBA8 second = target.read();
  EXPECT_FALSE(second.pixels == undrawn.pixels) << "the new target was not drawn into";
  EXPECT_TRUE(second.pixels == first.pixels) << "the new target's frame differs from the first";
  EXPECT_FALSE(undrawn.pixels == first.pixels);  // the control: the marker is not the picture
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace marble
