#pragma once
// Pass 2: the mesh seen from the camera into a lean G-buffer:
//   albedo  RGBA8          4 bytes  (the marble pattern, evaluated here by a program
//                                    specialized for the material's basis and mapping)
//   normal  RG16_SNORM     4 bytes  (octahedral, world space)
//   depth   DEPTH32F       4 bytes  (position is reconstructed from it)
// = 8 bytes per pixel plus depth.
#include "marble/gl/program_variants.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"
#include "marble/scene/material.h"

namespace marble {

class GeometryPass {
public:
  explicit GeometryPass(const ShaderLibrary& shaders);
  void resize(int width, int height);
  void run(const GpuMesh& mesh, const glm::mat4& model, const CameraMatrices& camera, const Material& material);
  GLuint albedoTexture() const { return albedo_.id(); }
  GLuint normalTexture() const { return normal_.id(); }
  GLuint depthTexture() const { return depth_.id(); }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * 12; }
  PassTimer& timer() { return timer_; }
  // Compiles the programs of every basis and mapping now (after a shader reload).
  void compileAll();

private:
  static std::vector<std::string> variantFor(const Material& m);
  gl::ProgramVariants programs_;
  gl::Texture albedo_, normal_, depth_;
  gl::Framebuffer fbo_;
  int width_ = 0, height_ = 0;
  PassTimer timer_;
};

}  // namespace marble
