#include "marble/render/light_depth_pass.h"

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>

#include "marble/gl/checked_calls.h"
#include "marble/render/face_culling.h"

namespace marble {
namespace {

// A mipmapped render target (all levels down to 1x1), clamped; read bilinearly within the nearest
// level (bounce.glsl picks a level per sample): trilinear cost the dragon's lighting pass ~1.5x.
gl::Texture makeMipmapped(GLenum internalFormat, int size) {
  int levels = 1;
  while ((size >> levels) > 0) ++levels;
  gl::Texture t = gl::Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), levels, internalFormat, size, size);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

// The uniforms both of the pass's programs (light_depth and light_layers) take to place the mesh
// in the light's view.
void setLightViewUniforms(gl::Program& program, const glm::mat4& model, const LightMatrices& light) {
  program.set("u_model", model);
  program.set("u_view_proj", light.viewProj);
  program.set("u_normal_matrix", glm::mat3(glm::inverseTranspose(model)));
  program.set("u_light_pos", light.position);
  program.set("u_light_dir", light.direction);
  program.set("u_light_directional", light.directional ? 1 : 0);
}

}  // namespace

LightDepthPass::LightDepthPass(const ShaderLibrary& shaders, int size)
    : size_(size),
      program_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "light_depth.frag.glsl"}}),
      layersProgram_(shaders, {{GL_VERTEX_SHADER, "mesh.vert.glsl"}, {GL_FRAGMENT_SHADER, "light_layers.frag.glsl"}}),
      // Nearest, not linear: at the object's silhouette seen from the light, blending a surface
      // distance with the "nothing hit" clear value would invent huge entry distances, hence
      // zero thickness and light leaking through past the terminator.
      // RG: the distance, and the cosine at which the light enters there (light_depth.frag.glsl).
      distance_(gl::makeTexture2D(GL_RG32F, size, size, GL_NEAREST)),
      depth_(gl::makeTexture2D(GL_DEPTH_COMPONENT32F, size, size, GL_LINEAR)),
      // The reflective shadow map at an eighth of the size, in a draw of its own: the bounce's
      // finest read (its centre sample, a disk of 1/32 of the map's width, bounce.glsl) is level 3
      // here, level 4 of session 7's 256² map: texels 64 of the full map's wide either way, so the
      // levels it reads are the same to within how the rasterizer covers a texel, and the draw
      // and its mipmaps cost less (docs/performance.md, "The bounce gathered coarsely"). 32-bit:
      // w is a texel's area, ~1e-5 scene units^2, below half float's normal range (and so is the
      // glossy weight a in the normal's alpha).
      bounceSize_(std::max(size / 8, 1)),
      bouncePosition_(makeMipmapped(GL_RGBA32F, bounceSize_)),
      bounceNormal_(makeMipmapped(GL_RGBA32F, bounceSize_)),
      bounceDepth_(gl::makeTexture2D(GL_DEPTH_COMPONENT32F, bounceSize_, bounceSize_, GL_NEAREST)),
      // A quarter of the light map's size (1.35 mm texels for the reference scenes): at an eighth,
      // the reflective shadow map's, the ten scenes' mean SSIM was 0.0002 lower (docs/quality.md,
      // "Twenty-second session"). Nearest: a blend of an entry or exit with "none" is meaningless.
      layersSize_(std::max(size / 4, 1)),
      layers_(gl::makeTexture2D(GL_RG32F, layersSize_, layersSize_, GL_NEAREST)),
      fbo_(gl::Framebuffer::create()),
      bounceFbo_(gl::Framebuffer::create()),
      layersFbo_(gl::Framebuffer::create()) {
  // Shadows read the depth with hardware comparison and bilinear filtering (PCF).
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, distance_.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  // The shader's outputs 1 and 2 go to the reflective shadow map's framebuffer only.
  glNamedFramebufferTexture(bounceFbo_.id(), GL_COLOR_ATTACHMENT1, bouncePosition_.id(), 0);
  glNamedFramebufferTexture(bounceFbo_.id(), GL_COLOR_ATTACHMENT2, bounceNormal_.id(), 0);
  const GLenum bounceBuffers[] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(bounceFbo_.id(), 3, bounceBuffers);
  glNamedFramebufferTexture(bounceFbo_.id(), GL_DEPTH_ATTACHMENT, bounceDepth_.id(), 0);
  glNamedFramebufferTexture(layersFbo_.id(), GL_COLOR_ATTACHMENT0, layers_.id(), 0);
}

void LightDepthPass::run(const GpuMesh& mesh, const glm::mat4& model, const LightMatrices& light) {
  timer_.begin();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_, size_);
  // Both faces where the mesh may show either to the light (a mesh with holes must still block
  // it); else only those facing it: the nearest surface is the same (face_culling.h).
  gl::setMeshPassState();
  cullFacesHiddenFromEye(cullsHiddenFaces_, mesh, light.viewProj * model);
  // "Nothing hit": a distance beyond every surface, no light entering.
  const float farValue[4] = {light.far + 1e3f, 0.0f, 0.0f, 0.0f};
  gl::clearFramebuffer(fbo_.id(), GL_COLOR, 0, farValue);
  const float one = 1.0f;
  gl::clearFramebuffer(fbo_.id(), GL_DEPTH, 0, &one);
  setLightViewUniforms(program_, model, light);
  glUseProgram(program_.id());
  mesh.draw();
  // The reflective shadow map: nothing there, nothing re-emitted (w = 0).
  glBindFramebuffer(GL_FRAMEBUFFER, bounceFbo_.id());
  glViewport(0, 0, bounceSize_, bounceSize_);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl::clearFramebuffer(bounceFbo_.id(), GL_COLOR, 1, zero);
  gl::clearFramebuffer(bounceFbo_.id(), GL_COLOR, 2, zero);
  gl::clearFramebuffer(bounceFbo_.id(), GL_DEPTH, 0, &one);
  mesh.draw();
  glDisable(GL_CULL_FACE);  // the layers draw both faces, and the other passes assume it off
  glGenerateTextureMipmap(bouncePosition_.id());
  glGenerateTextureMipmap(bounceNormal_.id());
  // The entry and exit layers (light_layers.frag.glsl): every fragment of both faces, each channel
  // keeping its nearest by MIN blending (no depth test: the nearest exit lies behind the nearest
  // entry). The blend and depth state is put back as the mesh passes left it.
  glBindFramebuffer(GL_FRAMEBUFFER, layersFbo_.id());
  glViewport(0, 0, layersSize_, layersSize_);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendEquation(GL_MIN);
  const float none[4] = {kNoLayer, kNoLayer, 0.0f, 0.0f};
  gl::clearFramebuffer(layersFbo_.id(), GL_COLOR, 0, none);
  setLightViewUniforms(layersProgram_, model, light);
  layersProgram_.set("u_none", kNoLayer);
  layersProgram_.set("u_outward", mesh.woundInward() ? -1.0f : 1.0f);
  glUseProgram(layersProgram_.id());
  mesh.draw();
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  timer_.end();
}

}  // namespace marble
