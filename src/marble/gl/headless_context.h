#pragma once
// An OpenGL 4.5 core context with no window: EGL on Mesa's surfaceless platform (llvmpipe
// here), or on the EGL device platform (a GPU driver such as NVIDIA's). Rendering goes into
// framebuffer objects. Throws EnvironmentError with one explaining line when no context can
// be had; it never silently degrades.
#include <string>

namespace marble {

class HeadlessContext {
public:
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace marble
