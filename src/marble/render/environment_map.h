#pragma once
// An environment map on the GPU: the GGX-prefiltered chain (environment/ggx_prefilter.h) as the
// mip levels of one equirectangular RGBA16F texture, and the diffuse SH terms, uploaded once per
// load; per frame only uniforms are set (shaders/environment.glsl reads them).
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "marble/environment/environment_lighting.h"
#include "marble/gl/program.h"

namespace marble {

class EnvironmentMap {
public:
  explicit EnvironmentMap(const PrefilteredEnvironment& env);

  GLuint texture() const { return texture_.id(); }
  // Sets environment.glsl's map uniforms (SH terms, lod mapping, rotation) on `program`.
  void setUniforms(const gl::Program& program, float rotationDeg) const;
  size_t bytes() const { return bytes_; }
  const std::string& source() const { return source_; }

private:
  gl::Texture texture_;
  std::array<glm::vec3, 9> diffuseTerms_{};
  float alpha1_ = 0.0f;
  int levels_ = 0;
  size_t bytes_ = 0;
  std::string source_;
};

}  // namespace marble
