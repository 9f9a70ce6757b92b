#pragma once
// An environment map on the GPU: the GGX-prefiltered chain (environment/ggx_prefilter.h) as the
// mip levels of one equirectangular RGBA16F texture, and the diffuse SH terms, uploaded once per
// load; per frame only uniforms are set (shaders/environment.glsl reads them).
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "marble/environment/environment_lighting.h"
#include "marble/gl/program.h"
#include "marble/render/shader_constants.h"
#include "marble/scene/scene.h"

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

// What environment.glsl is given for a frame. The kind (studio -- also used, at intensity 0,
// for none -- or map) is compiled into the programs that include it (ENV_KIND); the rest are
// uniforms, and the map's texture goes to unit kEnvMapUnit.
constexpr int kEnvStudio = shader::ENV_STUDIO, kEnvMap = shader::ENV_MAP;
constexpr GLuint kEnvMapUnit = shader::UNIT_ENV_MAP;  // u_env_map's binding
// `map`: the loaded map, or null when none is (a scene asking for a map then has no environment).
int environmentKind(const RenderSettings& settings, const EnvironmentMap* map);
std::string environmentDefine(const RenderSettings& settings, const EnvironmentMap* map);  // "ENV_KIND k"
void setEnvironmentUniforms(const gl::Program& program, const RenderSettings& settings, const EnvironmentMap* map);
// The studio's reflections are blurred over kStudioBlurPerRoughness x roughness radians
// (kStudioBlurPerRoughness in environment.glsl); a pass that calls env_radiance sets this with
// its roughness (u_studio_blur_cs: the cosine and sine of that angle, once per frame, not per pixel).
constexpr float kStudioBlurPerRoughness = 1.2f;
void setStudioBlurUniform(const gl::Program& program, float roughness);

}  // namespace marble
