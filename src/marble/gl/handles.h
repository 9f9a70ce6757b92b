#pragma once
// RAII owners of OpenGL objects: movable, never copyable; the destructor deletes the object.
// A default-constructed handle owns nothing (0) and needs no context (Magnum's NoCreate idea).
// Every handle created or deleted updates a live-object counter, so tests can check that
// nothing leaks over a long session.
#include <epoxy/gl.h>

#include <utility>

#include "marble/gl/draw_state_check.h"

namespace marble::gl {

// Count of live GL objects created through these handles (soak tests).
long& liveObjectCount();

template <typename Traits>
class Handle {
public:
  Handle() = default;
  static Handle create() {
    Handle h;
    h.id_ = Traits::create();
    if (h.id_) ++liveObjectCount();
    return h;
  }
  explicit Handle(GLuint adopt) : id_(adopt) {
    if (id_) ++liveObjectCount();
  }
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) {
      Traits::destroy(id_);
      --liveObjectCount();
      id_ = 0;
    }
  }

private:
  GLuint id_ = 0;
};

struct BufferTraits {
  static GLuint create() { GLuint id = 0; glCreateBuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayTraits {
  static GLuint create() { GLuint id = 0; glCreateVertexArrays(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct FramebufferTraits {
  static GLuint create() { GLuint id = 0; glCreateFramebuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct QueryTraits {
  static GLuint create() { GLuint id = 0; glCreateQueries(GL_TIME_ELAPSED, 1, &id); return id; }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct ProgramTraits {
  static GLuint create() { return glCreateProgram(); }
  static void destroy(GLuint id) {
    forgetProgramSamplers(id);  // GL reuses the name
    // A current program outlives its deletion (OpenGL 4.5, 7.3) and its samplers stay checked
    // at every later clear and draw (NVIDIA's driver does), while the textures on their units go.
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (static_cast<GLuint>(current) == id) glUseProgram(0);
    glDeleteProgram(id);
  }
};

struct SamplerTraits {
  static GLuint create() { GLuint id = 0; glCreateSamplers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};

using Buffer = Handle<BufferTraits>;
using Sampler = Handle<SamplerTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using TimerQuery = Handle<QueryTraits>;
using ProgramId = Handle<ProgramTraits>;

// Textures need their target at creation.
class Texture {
public:
  Texture() = default;
  static Texture create(GLenum target) {
    Texture t;
    glCreateTextures(target, 1, &t.id_);
    if (t.id_) ++liveObjectCount();
    return t;
  }
  ~Texture() { reset(); }
  Texture(Texture&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Texture& operator=(Texture&& o) noexcept {
    if (this != &o) { reset(); id_ = std::exchange(o.id_, 0); }
    return *this;
  }
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) { glDeleteTextures(1, &id_); --liveObjectCount(); id_ = 0; }
  }

private:
  GLuint id_ = 0;
};

// A 2D texture with immutable storage, clamped at the edges, filtered by `filter`
// (GL_NEAREST or GL_LINEAR) both ways: the one shape every render target here takes.
Texture makeTexture2D(GLenum internalFormat, int width, int height, GLenum filter);

// Sets what a pass that draws meshes relies on: depth test (less, writing), no blending,
// no culling (meshes with holes or inconsistent winding must still be whole).
void setMeshPassState();
// Sets what a full-screen pass relies on: no depth test, blending or culling.
void setScreenPassState();
// A full-screen pass over the surface only: the framebuffer has the G-buffer's depth attached
// (attachSurfaceDepth) and the depth test keeps the pixels where the camera saw the mesh (the
// full-screen triangle lies on the far plane, which the cleared background holds). llvmpipe
// tests depth before shading and skips each 4x4 block with no pixel left -- which a branch on
// the depth value inside the shader does not (both sides of a branch run under a mask): on
// the dragon at 800x800 the lighting pass went from 8.9 to 5.3 ms. A GPU's early depth test
// does the same. Depth writes are off: reading the depth texture while it is attached is then
// no feedback loop (OpenGL 4.5, 9.3.1: no texel is both written and read).
void setSurfaceOnlyScreenPassState();
// A full-screen pass that writes a depth buffer of its own from a shader's gl_FragDepth (the
// depth copies at a coarser resolution that setSurfaceOnlyScreenPassState later tests against:
// BlurDepthPass, BounceGridDepth): the test on and always passing, so every texel takes its
// pixel's depth, writes on. The caller clears the buffer to the far plane first.
void setDepthCopyScreenPassState();
// Attaches `depthTexture` (the G-buffer's) to `fbo` as its depth buffer, for
// setSurfaceOnlyScreenPassState.
inline void attachSurfaceDepth(GLuint fbo, GLuint depthTexture) {
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depthTexture, 0);
}

// Leaves no program current when it goes out of scope: what the renderer's entry points that
// draw hold. NVIDIA's driver checks the current program's samplers at clears as well as draws
// (docs/performance.md, "Eighteenth session: the GL state NVIDIA checks"), so a program left
// current after a frame is checked again at whatever the caller, or the next renderer, clears
// next, when the textures on its units may have gone.
class NoProgramCurrentOnExit {
public:
  NoProgramCurrentOnExit() = default;
  ~NoProgramCurrentOnExit() { glUseProgram(0); }
  NoProgramCurrentOnExit(const NoProgramCurrentOnExit&) = delete;
  NoProgramCurrentOnExit& operator=(const NoProgramCurrentOnExit&) = delete;
};

// One triangle covering the viewport, drawn with `program` (fullscreen.vert.glsl builds it from
// gl_VertexID; the core profile still wants a vertex array bound: `emptyVao`).
void drawFullscreenTriangle(GLuint program, GLuint emptyVao);

}  // namespace marble::gl
