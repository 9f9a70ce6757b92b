#include "marble/render/environment_map.h"

#include <algorithm>
#include <cmath>
#include <iterator>
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

namespace {
// The studio's softboxes (marble_shading.glsl, softbox(): their axes stay there): cone radius in
// radians and radiance.
struct StudioSoftbox {
  float radius, radiance;
};
constexpr StudioSoftbox kStudioSoftboxes[] = {{0.45f, 3.0f}, {0.18f, 4.0f}, {0.18f, 4.0f}};

// cos / sin of a value the compiler cannot fold: the shader compiler folds the constant edges'
// cos(r +- 0.02) with the C library's cosf / sinf, which GCC's own folding (correctly rounded)
// could differ from by an ulp.
float libraryCos(float x) {
  volatile float v = x;
  return std::cos(static_cast<float>(v));
}
float librarySin(float x) {
  volatile float v = x;
  return std::sin(static_cast<float>(v));
}
}  // namespace

void setStudioBlurUniform(const gl::Program& program, float roughness) {
  // What studio_radiance (marble_shading.glsl) computed per pixel before session 20, by the same
  // float operations in the same order (no contraction: -ffp-contract=off for this file), so the
  // pictures keep every bit.
  const float blur = kStudioBlurPerRoughness * roughness;
  const float c = std::cos(blur), s = std::sin(blur);
  glm::vec3 boxes[std::size(kStudioSoftboxes)];
  for (size_t i = 0; i < std::size(kStudioSoftboxes); ++i) {
    const float r = kStudioSoftboxes[i].radius;
    const float k = r / (r + blur);
    const float outer = libraryCos(r + 0.02f) * c - librarySin(r + 0.02f) * s;
    const float inner = blur >= r - 0.02f ? 1.0f : libraryCos(r - 0.02f) * c + librarySin(r - 0.02f) * s;
    boxes[i] = glm::vec3(kStudioSoftboxes[i].radiance * k * k, outer, inner);
  }
  glProgramUniform3fv(program.id(), program.location("u_studio_boxes"), static_cast<GLsizei>(std::size(boxes)), &boxes[0].x);
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
