#include "marble/render/environment_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace marble {

// The largest finite half float: brighter texels (a captured sun) would become infinite in
// RGBA16F. Only the sharpest levels can hold such values; the blurred levels and the SH were
// computed from the unclamped floats, so the sun's energy still reaches rough and diffuse light.
constexpr float kMaxHalf = 65504.0f;

EnvironmentMap::EnvironmentMap(const PrefilteredEnvironment& env)
    : texture_(gl::Texture::create(GL_TEXTURE_2D)),
      diffuseTerms_(shDiffuseTerms(env.sh)),
      alpha1_(env.alpha1),
      levels_(static_cast<int>(env.levels.size())),
      source_(env.source) {
  const ImageRGBF& base = env.levels.front();
  glTextureStorage2D(texture_.id(), levels_, GL_RGBA16F, base.width, base.height);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);         // longitude wraps around
  glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // latitude stops at the poles
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  std::vector<float> clamped;
  for (int k = 0; k < levels_; ++k) {
    const ImageRGBF& level = env.levels[static_cast<size_t>(k)];
    clamped.resize(level.pixels.size());
    std::transform(level.pixels.begin(), level.pixels.end(), clamped.begin(), [](float v) { return std::min(v, kMaxHalf); });
    // Row 0 (the top, +Y) goes to t = 0, as environment.glsl's v = acos(d.y) / pi expects.
    glTextureSubImage2D(texture_.id(), k, 0, 0, level.width, level.height, GL_RGB, GL_FLOAT, clamped.data());
    bytes_ += static_cast<size_t>(level.width) * static_cast<size_t>(level.height) * 8;
  }
}

void EnvironmentMap::setUniforms(const gl::Program& p, float rotationDeg) const {
  glProgramUniform3fv(p.id(), p.location("u_env_sh"), 9, &diffuseTerms_[0].x);
  p.set("u_env_alpha1", alpha1_);
  p.set("u_env_max_lod", static_cast<float>(levels_ - 1));
  const float r = glm::radians(rotationDeg);
  p.set("u_env_rotation", glm::vec2(std::cos(r), std::sin(r)));
}

int environmentKind(const RenderSettings& settings, const EnvironmentMap* map) {
  return settings.environment == Environment::Map && map ? kEnvMap : kEnvStudio;
}

std::string environmentDefine(const RenderSettings& settings, const EnvironmentMap* map) {
  return "ENV_KIND " + std::to_string(environmentKind(settings, map));
}

void setStudioBlurUniform(const gl::Program& program, float roughness) {
  const float blur = kStudioBlurPerRoughness * roughness;
  program.set("u_studio_blur_cs", glm::vec2(std::cos(blur), std::sin(blur)));
}

void setEnvironmentUniforms(const gl::Program& p, const RenderSettings& settings, const EnvironmentMap* map) {
  const bool useMap = environmentKind(settings, map) == kEnvMap;
  const bool lit = settings.environment == Environment::Studio || useMap;
  p.set("u_env_intensity", lit ? settings.environment_intensity : 0.0f);
  if (useMap) {
    map->setUniforms(p, settings.environment_rotation_deg);
    glBindTextureUnit(kEnvMapUnit, map->texture());
  }
}

}  // namespace marble
