#include "marble/render/post_pass.h"

#include <cmath>

#include "marble/render/frame_uniforms.h"
#include "marble/render/lighting_pass.h"
#include "marble/render/subsurface_blur_pass.h"

namespace marble {

float fxaaLuma(const glm::vec3& displayColor) { return glm::dot(displayColor, glm::vec3(0.299f, 0.587f, 0.114f)); }

PostPass::PostPass(const ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "post.frag.glsl"}}),
      emptyVao_(gl::VertexArray::create()) {
  programs_.get({"COMPOSE_MARBLE 1", environmentDefine(RenderSettings{}, nullptr)});  // a broken shader shows at once
}

void PostPass::compileAll() {
  for (const char* compose : {"COMPOSE_MARBLE 0", "COMPOSE_MARBLE 1"})
    for (int kind : {kEnvStudio, kEnvMap}) programs_.get({compose, "ENV_KIND " + std::to_string(kind)});
}

void PostPass::run(const PostInputs& in, const Scene& scene, const PostView& view, GLuint targetFbo, int width,
                   int height, const ScreenRect& rect, Output output) {
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
    glClearBufferfv(GL_COLOR, 0, &clear.x);
    scissorTo(rect);
  }
  const GLuint textures[] = {in.hdr, in.depth, in.blurred, 0, in.albedo, in.normal, in.lightShadow};  // unit 3 unused
  glBindTextures(0, 7, textures);
  const int envKind = environmentKind(settings, view.environment);
  const gl::Program& p = programs_.get((marble ? 2u : 0u) + static_cast<uint32_t>(envKind), [&] {
    return std::vector<std::string>{marble ? "COMPOSE_MARBLE 1" : "COMPOSE_MARBLE 0",
                                    "ENV_KIND " + std::to_string(envKind)};
  });
  p.set("u_output_linear", linearOutput ? 1 : 0);
  p.set("u_luma_alpha", output == Output::DisplayWithLuma ? 1 : 0);
  p.set("u_tone_map", marble ? 1 : 0);
  p.set("u_exposure_scale", std::exp2(settings.exposure));
  p.set("u_paint_background", wholeFrame ? 0 : 1);
  p.set("u_background", settings.background);
  if (marble) {
    setFrameUniforms(p, view.camera, view.light, scene.light, view.lightTexelWorld);
    p.set("u_ior", scene.material.ior);
    p.set("u_roughness", scene.material.roughness);
    setEnvironmentUniforms(p, settings, view.environment);
    setStudioBlurUniform(p, scene.material.roughness);
    setSubsurfaceUniforms(p, view.camera, scene, height);
  }
  gl::drawFullscreenTriangle(p.id(), emptyVao_.id());
  scissorOff();
  timer_.end();
}

}  // namespace marble
