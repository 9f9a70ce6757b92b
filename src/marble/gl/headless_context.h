#pragma once
// An OpenGL 4.5 core context with no window: EGL on Mesa's surfaceless platform (llvmpipe
// here), or on the EGL device platform (a GPU driver such as NVIDIA's). Rendering goes into
// framebuffer objects. Throws EnvironmentError with one explaining line when no context can
// be had; it never silently degrades. Contexts nest: the one made last is current, and when it
// goes, whatever was current before it (another HeadlessContext, or an embedding program's own
// EGL context) is current again; the EGL display is terminated only with its last user.
#include <string>

namespace marble {

namespace detail {
// What EGL had current when a HeadlessContext was made (EGLDisplay, EGLSurface ×2, EGLContext),
// kept as void* so that this header needs no EGL.
struct CurrentEgl {
  void* display = nullptr;
  void* draw = nullptr;
  void* read = nullptr;
  void* context = nullptr;
};
}  // namespace detail

class HeadlessContext {
public:
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
  detail::CurrentEgl previous_;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace marble
