#include "marble/render/lighting_pass.h"

#include <algorithm>

#include "marble/gl/checked_calls.h"
#include "marble/gl/packed_float_pair.h"
#include "marble/render/frame_uniforms.h"
#include "marble/render/material_uniforms.h"
#include "marble/render/shader_constants.h"
#include "marble/render/subsurface_profile.h"
#include "marble/scene/material_scattering.h"
#include "marble/scene/slab_transport.h"

namespace marble {

LightingPass::LightingPass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "lighting.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  // The default mode's, so a broken shader shows at once.
  programs_.get(variantFor(RenderMode::Marble, environmentDefine(RenderSettings{}, nullptr), Light{}.type == LightType::Directional));
}

std::vector<std::string> LightingPass::variantFor(RenderMode mode, const std::string& environment, bool directional) {
  return {"LIGHTING_MODE " + std::to_string(static_cast<int>(mode)), environment,
          lightKindDefine(directional)};
}

void LightingPass::compileAll() {
  for (size_t i = 0; i < renderModeNames().size(); ++i)
    for (int kind : {kEnvStudio, kEnvMap})
      if (static_cast<RenderMode>(i) != RenderMode::Floor)
        for (bool directional : {false, true})
          programs_.get(variantFor(static_cast<RenderMode>(i), "ENV_KIND " + std::to_string(kind), directional));
}

void LightingPass::resize(int width, int height, int enteringScale, GLuint depthTexture, GLuint enteringDepth) {
  if (width != width_ || height != height_ || enteringScale != enteringScale_ || !fbo_) {
    width_ = width;
    height_ = height;
    enteringScale_ = enteringScale;
    enteringWidth_ = (width + enteringScale - 1) / enteringScale;  // rounded up, as the blur's
    enteringHeight_ = (height + enteringScale - 1) / enteringScale;
    hdr_ = gl::makeTexture2D(GL_RGBA16F, width, height, GL_LINEAR);
    entering_ = gl::makeTexture2D(GL_RGBA16F, enteringWidth_, enteringHeight_, GL_LINEAR);
    mirrorHit_ = gl::makeTexture2D(GL_RG32F, enteringWidth_, enteringHeight_, GL_NEAREST);  // whole pixels
    // One framebuffer per kind of output, so a mode writes (and clears) only what it uses.
    fbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, hdr_.id(), 0);
    enteringFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(enteringFbo_.id(), GL_COLOR_ATTACHMENT1, entering_.id(), 0);
    glNamedFramebufferTexture(enteringFbo_.id(), GL_COLOR_ATTACHMENT2, mirrorHit_.id(), 0);
    const GLenum bufs[] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(enteringFbo_.id(), 3, bufs);
  }
  // Borrowed: attached every time, never compared by name (gl::Borrowed).
  gl::attachSurfaceDepth(fbo_.id(), depthTexture);
  gl::attachSurfaceDepth(enteringFbo_.id(), enteringDepth);
}

void LightingPass::run(const LightingInputs& in, const CameraMatrices& camera, const LightMatrices& lightM,
                       const Light& light, const Material& m, const Scene& scene, float lightTexelWorld,
                       const ScreenRect& rect, const EnvironmentMap* environment) {
  const RenderSettings& settings = scene.render;
  const bool marble = settings.mode == RenderMode::Marble;
  const GLuint fbo = marble ? enteringFbo_.id() : fbo_.id();
  const bool wholeFrame = settings.mode == RenderMode::LightDepth;  // the light's own map, shown whole
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, marble ? enteringWidth_ : width_, marble ? enteringHeight_ : height_);
  if (wholeFrame)
    gl::setScreenPassState();
  else
    gl::setSurfaceOnlyScreenPassState();
  // Outside the rectangle, and on the background, there is no surface: zero light.
  const float zero[4] = {0, 0, 0, 0};
  gl::clearFramebuffer(fbo, GL_COLOR, marble ? 1 : 0, zero);
  const float none[4] = {-1, -1, 0, 0};  // no mirror hit
  if (marble) gl::clearFramebuffer(fbo, GL_COLOR, 2, none);
  if (marble)
    scissorTo(scaledDown(rect, enteringScale_));
  else if (!wholeFrame)
    scissorTo(rect);
  const GLuint textures[] = {in.albedo, in.normal, in.depth, in.lightDistance, in.lightDepth};
  glBindTextures(shader::UNIT_LIGHTING_ALBEDO, 5, textures);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE, in.bounce);
  glBindTextureUnit(shader::UNIT_LIGHTING_BOUNCE_ENTRY, in.bounceEntry);
  glBindTextureUnit(shader::UNIT_LIGHTING_LIGHT_LAYERS, in.lightLayers);
  const int envKind = environmentKind(settings, environment);
  const gl::Program& p = programs_.get(
      (static_cast<uint32_t>(settings.mode) * 2u + static_cast<uint32_t>(envKind)) * 2u + (lightM.directional ? 1u : 0u),
      [&] { return variantFor(settings.mode, "ENV_KIND " + std::to_string(envKind), lightM.directional); });
  setFrameUniforms(p, camera, lightM, light, lightTexelWorld);
  p.set("u_camera_near_far", glm::vec2(camera.near, camera.far));
  p.set("u_light_near_far", glm::vec2(lightM.near, lightM.far));
  uploadMaterialUniforms(p, m);
  p.set("u_mm_per_unit", scene.mm_per_unit);
  // Derived from sigma_a_mm, sigma_s_mm: not parameters of their own. Cut from the walk's table
  // again only when they change, not each time the camera or the light moves.
  if (!slabFor_ || slabFor_->first != m.sigma_a_mm || slabFor_->second != m.sigma_s_mm) {
    slab_ = slabTransportFor(m);
    // The transmission's chord across an edge of the light's map (transmission_chord.glsl): its
    // decay per mm, kept above 0.001 (a stone that absorbs nothing, where it is the texels' mean
    // chord).
    chordDecayMm_ = std::max(diffusionAttenuationMm(m), 1.0e-3f);
    // A hidden lit face's light spread by the walk (shaders/mirror_lit_face.glsl).
    litFaceRingMm_ = walkRingRadiusMm(walkShape(m));
    // The table per channel as segments, (ln T at node k, at node k + 1): the shader reads a
    // segment's two ends in one indexed read per channel (slab_segment in lighting.frag.glsl), the
    // two floats' bits packed into one 64-bit element (node k in the low word: unpackDouble2x32's x).
    for (int k = 0; k + 1 < kSlabTransportNodes; ++k)
      for (int c = 0; c < 3; ++c) slabSegments_[c][k] = gl::packFloatPair(slab_.lnT[k][c], slab_.lnT[k + 1][c]);
    slabFor_ = std::pair(m.sigma_a_mm, m.sigma_s_mm);
  }
  glProgramUniform1dv(p.id(), p.location("u_slab_segment_r"), kSlabTransportNodes - 1, slabSegments_[0].data());
  glProgramUniform1dv(p.id(), p.location("u_slab_segment_g"), kSlabTransportNodes - 1, slabSegments_[1].data());
  glProgramUniform1dv(p.id(), p.location("u_slab_segment_b"), kSlabTransportNodes - 1, slabSegments_[2].data());
  p.set("u_slab_tau_max", slab_.tauMax);
  p.set("u_slab_sigma_t_mm", slab_.sigmaTMm);
  p.set("u_chord_decay", chordDecayMm_ * scene.mm_per_unit);
  p.set("u_lit_face_ring_mm", litFaceRingMm_);
  p.set("u_scale", marble ? enteringScale_ : 1);
  setBounceGridUniforms(p, in.bounceGrid);
  setEnvironmentUniforms(p, settings, environment);
  gl::drawFullscreenTriangle(p.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
