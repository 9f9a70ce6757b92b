#include "marble/render/subsurface_blur_pass.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "marble/gl/checked_calls.h"
#include "marble/render/shader_constants.h"

namespace marble {

namespace {
// Taps per side at most (the shader's MAX_TAPS).
constexpr int kMaxTaps = shader::MAX_TAPS;
// Taps per side per square root of the reach in blur texels. The taps are spaced quadratically
// (subsurfaceKernel), so 1 sqrt(texels) of them put the first within a texel of the centre, where
// the profile is steepest, and the last two 2 sqrt(texels) apart. Since session 18 the reach is the
// walk's, 2.5x Burley's 8 d (16.2 against 6.5 mm in the stone), and 1 sqrt(texels) gives
// as many taps as 1.5 did over the old reach (the dragon at 800x800: 6): the outer taps' weights are
// the walk's faint tail (under 2 % of red per tap), and SSIM against Cycles is the same as with 1.5
// to 0.0004 in all ten reference scenes (docs/quality.md, "Eighteenth session"), for 1.4x the
// blur's cost. (Before session 18, over Burley's reach: 1 sqrt(texels) left the outer taps so far
// apart on the profile's steeper tail that a back-lit sphere's glow showed a step,
// tests/transmission_seams_gl_test.cpp at 1.02x its threshold; a tap per texel, up to 9: the blur
// pass 2.2x as costly on the dragon at 800x800, SSIM the same to 0.001.)
constexpr float kTapsPerRootTexel = 1.0f;
}  // namespace

SubsurfaceBlurPass::SubsurfaceBlurPass(const ShaderLibrary& shaders)
    : programs_(shaders,
                {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "subsurface_blur.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()),
      nearestSampler_(gl::Sampler::create()) {
  glSamplerParameteri(nearestSampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(nearestSampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(nearestSampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(nearestSampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  program(kMaxTaps);  // so a broken shader shows at once
}

const gl::Program& SubsurfaceBlurPass::program(int taps) {
  return programs_.get(static_cast<uint32_t>(taps),
                       [taps] { return std::vector<std::string>{"BLUR_TAPS " + std::to_string(taps)}; });
}

void SubsurfaceBlurPass::compileAll() {
  for (int taps = 1; taps <= kMaxTaps; ++taps) program(taps);
}

int subsurfaceScale(const RenderSettings& settings) {
  return settings.subsurface_resolution == SubsurfaceResolution::Half ? 2 : 1;
}

void SubsurfaceBlurPass::resize(int width, int height, int scale, GLuint depthTexture) {
  const int w = (width + scale - 1) / scale, h = (height + scale - 1) / scale;  // rounded up
  if (w != width_ || h != height_ || !resultFbo_) {
    width_ = w;
    height_ = h;
    horizontal_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_LINEAR);
    // Nearest: its one reader, the post pass, takes whole texels (upsample_blurred), through the
    // sampler, which llvmpipe does in fewer instructions than texelFetch (nearest_texel.glsl).
    result_ = gl::makeTexture2D(GL_RGBA16F, w, h, GL_NEAREST);
    horizontalFbo_ = gl::Framebuffer::create();
    resultFbo_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(horizontalFbo_.id(), GL_COLOR_ATTACHMENT0, horizontal_.id(), 0);
    glNamedFramebufferTexture(resultFbo_.id(), GL_COLOR_ATTACHMENT0, result_.id(), 0);
  }
  // Borrowed: attached every time, never compared by name (gl::Borrowed).
  gl::attachSurfaceDepth(horizontalFbo_.id(), depthTexture);
  gl::attachSurfaceDepth(resultFbo_.id(), depthTexture);
}

namespace {
float pixelsPerMmAtUnitDepth(const CameraMatrices& camera, const Scene& scene, int height) {
  // Pixels per scene unit at view distance 1 (full resolution): proj[1][1] maps tan(fov/2)
  // to 1 = height/2 px.
  return camera.proj[1][1] * 0.5f * static_cast<float>(height) / scene.mm_per_unit;
}
}  // namespace

int subsurfaceTaps(const CameraMatrices& camera, const Scene& scene, int height) {
  // The widest the profile can be on screen: at the near plane (fitted to the object's
  // bounding sphere, so no surface is nearer), in blur texels.
  const float texels = subsurfaceReachMm(scene.material) * pixelsPerMmAtUnitDepth(camera, scene, height) /
                       (std::max(camera.near, 1e-3f) * static_cast<float>(subsurfaceScale(scene.render)));
  return std::clamp(static_cast<int>(std::ceil(kTapsPerRootTexel * std::sqrt(texels))), 1, kMaxTaps);
}

void setSubsurfaceUniforms(const gl::Program& p, const CameraMatrices& camera, const Scene& scene, int height) {
  p.set("u_near_far", glm::vec2(camera.near, camera.far));
  p.set("u_mm_per_unit", scene.mm_per_unit);
  p.set("u_pixels_per_mm_at_unit_depth", pixelsPerMmAtUnitDepth(camera, scene, height));
  p.set("u_reach_mm", subsurfaceReachMm(scene.material));
  p.set("u_scale", subsurfaceScale(scene.render));
}

void SubsurfaceBlurPass::run(const SubsurfaceBlurInputs& in, const CameraMatrices& camera, const Scene& scene,
                             int height, const ScreenRect& rect) {
  timer_.begin();
  gl::setSurfaceOnlyScreenPassState();
  glViewport(0, 0, width_, height_);
  // The taps: the diffusion profile's marginal (subsurface_profile.h) out to its reach, with as
  // many taps as that reach spans on screen (the dragon filling an 800-pixel frame: 6 per side).
  // Cut again only when the stone or the tap count changes.
  const WalkShape walk = walkShape(scene.material);
  const int taps = subsurfaceTaps(camera, scene, height);
  const float reachMm = subsurfaceReachMm(scene.material);
  // The kernel's core is matched in half a blur texel at the object's centre (the origin: meshes
  // are centred there), whose view depth is -view[3][2]; nearer or farther parts have smaller or
  // larger texels (the dragon's scenes: within 20 %, where the core changes by under 0.02).
  const float centreDepth = std::max(-camera.view[3][2], camera.near);
  const float coreHalfWidthMm = 0.5f * static_cast<float>(subsurfaceScale(scene.render)) * centreDepth /
                                pixelsPerMmAtUnitDepth(camera, scene, height);
  if (!(walk == kernelWalk_) || reachMm != kernelReachMm_ || taps != kernel_.taps ||
      coreHalfWidthMm != kernelCoreHalfWidthMm_ || !kernelValid_) {
    kernel_ = subsurfaceKernel(walk, reachMm, taps, coreHalfWidthMm);
    kernelWalk_ = walk;
    kernelReachMm_ = reachMm;
    kernelCoreHalfWidthMm_ = coreHalfWidthMm;
    kernelValid_ = true;
  }
  // The tap count is a constant of the program (BLUR_TAPS): shaders/subsurface_blur.frag.glsl says why.
  const gl::Program& p = program(kernel_.taps);
  glProgramUniform3fv(p.id(), p.location("u_weights"), kernel_.taps + 1, &kernel_.weights[0].x);
  glProgramUniform1fv(p.id(), p.location("u_offsets_mm"), kernel_.taps + 1, kernel_.offsetsMm.data());
  glProgramUniform3fv(p.id(), p.location("u_decay_per_mm"), kernel_.taps + 1, &kernel_.decayPerMm[0].x);
  setSubsurfaceUniforms(p, camera, scene, height);
  glUseProgram(p.id());
  glBindVertexArray(emptyVao_.id());

  // Outside the (half-resolution) rectangle: no surface, zero light and zero coverage.
  const float zero[4] = {0, 0, 0, 0};
  gl::clearFramebuffer(horizontalFbo_.id(), GL_COLOR, 0, zero);
  gl::clearFramebuffer(resultFbo_.id(), GL_COLOR, 0, zero);
  scissorTo(scaledDown(rect, subsurfaceScale(scene.render)));
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT, in.entering);
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT_TEXELS, in.entering);
  glBindSampler(shader::UNIT_SCREEN_INPUT_TEXELS, nearestSampler_.id());
  // The lighting pass's own texels, for the kernel's core (second pass only).
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT_OWN, in.entering);
  glBindSampler(shader::UNIT_SCREEN_INPUT_OWN, nearestSampler_.id());
  p.set("u_core", glm::vec3(0.0f));
  p.set("u_direction", glm::vec2(1, 0));
  glBindFramebuffer(GL_FRAMEBUFFER, horizontalFbo_.id());
  gl::drawArrays(GL_TRIANGLES, 0, 3);

  glBindTextureUnit(shader::UNIT_SCREEN_INPUT, horizontal_.id());
  glBindTextureUnit(shader::UNIT_SCREEN_INPUT_TEXELS, horizontal_.id());
  p.set("u_core", kernel_.core);
  p.set("u_direction", glm::vec2(0, 1));
  glBindFramebuffer(GL_FRAMEBUFFER, resultFbo_.id());
  gl::drawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(shader::UNIT_SCREEN_INPUT_TEXELS, 0);  // the unit's textures' own filters again for other passes
  glBindSampler(shader::UNIT_SCREEN_INPUT_OWN, 0);
  scissorOff();
  timer_.end();
}

}  // namespace marble
