#include "marble/render/post_pass.h"

#include <cmath>

#include "marble/gl/checked_calls.h"
#include "marble/noise/turbulence_grid.h"
#include "marble/render/albedo_pass.h"
#include "marble/render/frame_uniforms.h"
#include "marble/render/lighting_pass.h"
#include "marble/render/material_uniforms.h"
#include "marble/render/shader_constants.h"
#include "marble/render/subsurface_blur_pass.h"
#include "marble/scene/material_scattering.h"

namespace marble {

float seenVeinAttenuation(const Scene& scene) {
  if (scene.material.vein_model == VeinModel::Paper) return 0.0f;
  return diffusionAttenuationMm(scene.material) * scene.mm_per_unit;
}

float fxaaLuma(const glm::vec3& displayColor) { return glm::dot(displayColor, glm::vec3(0.299f, 0.587f, 0.114f)); }

namespace {
std::vector<std::string> variantDefines(bool marble, int envKind, DiffuseSource source, const Material& material,
                                        GLuint turbulenceGrid, SurfaceReuse reuse, bool directional) {
  std::vector<std::string> d = {marble ? "COMPOSE_MARBLE 1" : "COMPOSE_MARBLE 0", "ENV_KIND " + std::to_string(envKind),
                                "DIFFUSE_SOURCE " + std::to_string(marble ? static_cast<int>(source) : 2),
                                lightKindDefine(directional)};
  if (marble && source == DiffuseSource::Pattern) {
    for (std::string& p : patternDefines(material, turbulenceGrid)) d.push_back(std::move(p));
    d.push_back("SURFACE_REUSE " + std::to_string(static_cast<int>(reuse)));
  }
  return d;
}
}  // namespace

PostPass::PostPass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "post.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  // The default material's first frame, so a broken shader shows at once.
  program(true, kEnvStudio, DiffuseSource::Pattern, Material{}, 0, Light{}.type == LightType::Directional);
}

const gl::Program& PostPass::program(bool marble, int envKind, DiffuseSource source, const Material& material,
                                     GLuint turbulenceGrid, bool directional, SurfaceReuse reuse) {
  directional = marble && directional;  // only the marble composition lights anything here
  const bool pattern = marble && source == DiffuseSource::Pattern;
  const uint32_t s = marble ? static_cast<uint32_t>(source) : 2u;
  const uint32_t r = pattern ? static_cast<uint32_t>(reuse) : 0u;
  const uint32_t patternKey = pattern ? patternVariantKey(material, turbulenceGrid) : 0u;
  const uint32_t key = (marble ? 1u : 0u) | static_cast<uint32_t>(envKind) << 1 | s << 2 | r << 4 |
                       (directional ? 1u : 0u) << 6 | patternKey << 7;
  return programs_.get(key, [&] {
    return variantDefines(marble, envKind, source, material, turbulenceGrid, pattern ? reuse : SurfaceReuse::None,
                          directional);
  });
}

GLuint PostPass::surfaceLightTexture() {
  if (!surfaceLight_) surfaceLight_ = gl::makeTexture2D(GL_RGBA32F, width_, height_, GL_NEAREST);
  return surfaceLight_.id();
}

GLuint PostPass::surfaceReflectedTexture() {
  if (!surfaceReflected_) surfaceReflected_ = gl::makeTexture2D(GL_RGBA32F, width_, height_, GL_NEAREST);
  return surfaceReflected_.id();
}

void PostPass::compileAll() {
  for (bool d : {false, true}) {  // the light's kind (LIGHT_DIRECTIONAL)
    for (int kind : {kEnvStudio, kEnvMap}) {
      program(false, kind, DiffuseSource::Stored, Material{}, 0, d);
      program(true, kind, DiffuseSource::Stored, Material{}, 0, d);
      program(true, kind, DiffuseSource::StoredAlbedo, Material{}, 0, d);
      for (NoiseBasis b : {NoiseBasis::Value, NoiseBasis::Perlin})
        for (PatternMapping m : {PatternMapping::Planar, PatternMapping::Triplanar, PatternMapping::Solid}) {
          Material material;
          material.basis = b;
          material.mapping = m;
          program(true, kind, DiffuseSource::Pattern, material, 0, d);
          if (turbulenceGridDimensions(material) > 0) program(true, kind, DiffuseSource::Pattern, material, 1, d);
        }
      // A pattern-only frame's two (SurfaceReuse), for the default material.
      program(true, kind, DiffuseSource::Pattern, Material{}, 0, d, SurfaceReuse::Store);
      program(true, kind, DiffuseSource::Pattern, Material{}, 0, d, SurfaceReuse::Read);
      for (VeinModel v : {VeinModel::Network, VeinModel::Breccia}) {  // solid whatever the mapping
        Material material;
        material.vein_model = v;
        program(true, kind, DiffuseSource::Pattern, material, 0, d);
        program(true, kind, DiffuseSource::Pattern, material, 1, d);
      }
    }
  }
}

void PostPass::resize(int width, int height) {
  if (width == width_ && height == height_ && diffuse_) return;
  width_ = width;
  height_ = height;
  diffuse_ = gl::makeTexture2D(GL_RGBA16F, width, height, GL_NEAREST);
  surfaceLight_ = {};  // made again at the new size when next needed
  surfaceReflected_ = {};
}

void PostPass::run(const PostInputs& in, const Scene& scene, const PostView& view, GLuint targetFbo, int width,
                   int height, const ScreenRect& rect, Output output, DiffuseSource source, SurfaceReuse reuse) {
  if (scene.render.mode != RenderMode::Marble || source != DiffuseSource::Pattern) reuse = SurfaceReuse::None;
  const bool linearOutput = output == Output::Linear;
  const RenderSettings& settings = scene.render;
  const bool marble = settings.mode == RenderMode::Marble;
  const bool wholeFrame = settings.mode == RenderMode::LightDepth;  // not a view of the G-buffer
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glViewport(0, 0, width, height);
  if (wholeFrame)
    gl::setScreenPassState();
  else
    gl::setSurfaceOnlyScreenPassState();
  if (!wholeFrame) {
    // Where the mesh cannot be: the background colour (a display colour, as the shader
    // paints it), or zero light and zero coverage for the linear picture.
    const glm::vec3 background = glm::clamp(settings.background, 0.0f, 1.0f);
    // Alpha as the shader writes it: coverage 0, luma, or 1.
    const float alpha = output == Output::DisplayWithLuma ? fxaaLuma(background) : 1.0f;
    const glm::vec4 clear = linearOutput ? glm::vec4(0.0f) : glm::vec4(background, alpha);
    gl::clearBoundFramebuffer(GL_COLOR, 0, &clear.x);
    scissorTo(rect);
  }
  // The outputs this source writes besides the picture (post.frag.glsl): the diffuse part at 1,
  // the albedo at 2.
  // (SurfaceReuse::Store: the upsampled light at 3, the reflected light at 4.)
  const GLenum all[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3,
                        GL_COLOR_ATTACHMENT4};
  const GLsizei outputs = !marble || source == DiffuseSource::Stored ? 1
                          : source == DiffuseSource::StoredAlbedo     ? 2
                          : reuse == SurfaceReuse::Store              ? 5
                                                                      : 3;
  glNamedFramebufferDrawBuffers(targetFbo, outputs, all);
  const GLuint textures[] = {in.hdr, in.depth, in.blurred, diffuse_.id(), in.albedo, in.normal, in.lightShadow};
  glBindTextures(shader::UNIT_POST_HDR, 7, textures);
  if (marble) glBindTextureUnit(shader::UNIT_POST_MIRROR_HIT, in.mirrorHit);
  if (reuse == SurfaceReuse::Read) {
    glBindTextureUnit(shader::UNIT_POST_SURFACE_LIGHT, surfaceLightTexture());
    glBindTextureUnit(shader::UNIT_POST_SURFACE_REFLECTED, surfaceReflectedTexture());
  }
  const int envKind = environmentKind(settings, view.environment);
  const gl::Program& p = program(marble, envKind, source, scene.material, view.turbulenceGrid, view.light.directional, reuse);
  p.set("u_output_linear", linearOutput ? 1 : 0);
  p.set("u_luma_alpha", output == Output::DisplayWithLuma ? 1 : 0);
  p.set("u_tone_map", marble ? 1 : 0);
  p.set("u_exposure_scale", std::exp2(settings.exposure));
  p.set("u_paint_background", wholeFrame ? 0 : 1);
  p.set("u_background", settings.background);
  if (marble) {
    setFrameUniforms(p, view.camera, view.light, scene.light, view.lightTexelWorld);
    uploadMaterialUniforms(p, scene.material);  // the gloss, and the pattern when it evaluates it
    setEnvironmentUniforms(p, settings, view.environment);
    setStudioBlurUniform(p, scene.material.roughness);
    if (source == DiffuseSource::Pattern) {
      setPatternUniforms(p, view.model, view.camera, view.turbulenceGrid);
      // The vein models seen through the polish (pattern_core.glsl), per object unit.
      p.set("u_pat_seen_sigma_tr", seenVeinAttenuation(scene));
      p.set("u_pat_seen_eta", 1.0f / std::max(scene.material.ior, 1.0f));
    }
    setSubsurfaceUniforms(p, view.camera, scene, height);
  }
  gl::drawFullscreenTriangle(p.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
