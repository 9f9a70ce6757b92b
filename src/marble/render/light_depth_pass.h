#pragma once
// Pass 1: the mesh seen from the light into a map of world-space distances (R32F) with its
// own depth buffer. Read by the lighting pass for thickness and shadows; beside it a reflective
// shadow map with mipmaps at an eighth of the size, drawn separately (light_depth.frag.glsl), for the
// `marble` mode's diffuse bounce.
#include "marble/gl/program.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"

namespace marble {

class LightDepthPass {
public:
  LightDepthPass(const ShaderLibrary& shaders, int size = 1024);
  // The depth map and the reflective shadow map keep the nearest surface, so they do not draw the
  // faces no ray from the light meets first (render/face_culling.h) unless switched off; the
  // entry and exit layers need both faces and draw them.
  void run(const GpuMesh& mesh, const glm::mat4& model, const LightMatrices& light);
  // For tests: whether hidden faces are culled (on by default).
  void setCullsHiddenFaces(bool on) { cullsHiddenFaces_ = on; }
  GLuint distanceTexture() const { return distance_.id(); }
  GLuint depthTexture() const { return depth_.id(); }  // compare mode on, for sampler2DShadow
  // The reflective shadow map: world position x w, w (RGBA32F) and the unit normal with the
  // glossy emitters' grazing weight a (RGBA32F: a is an area, like w), mipmapped: a level's
  // texel is the w-weighted mean of the texels under it.
  GLuint bouncePositionTexture() const { return bouncePosition_.id(); }
  GLuint bounceNormalTexture() const { return bounceNormal_.id(); }
  // At a quarter of the size, the distance from the light to the nearest surface facing it and to
  // the nearest facing away (RG32F, nearest; kNoLayer where there is none): where the light enters
  // and leaves the first part it meets (light_layers.frag.glsl), for the hidden mirror image
  // (hidden_mirror.glsl), and for the bounce's visibility through the stone (bounce_through_stone.glsl).
  GLuint layersTexture() const { return layers_.id(); }
  static constexpr float kNoLayer = 1e30f;
  int size() const { return size_; }
  int bounceSize() const { return bounceSize_; }  // the reflective shadow map's finest width
  int layersSize() const { return layersSize_; }  // the layers' width
  // distance 8 + depth 4 bytes a texel; the reflective shadow map's position 16 + normal 16 (its
  // mipmaps a third more) + depth 4 at its own size; the layers 8 at theirs.
  size_t bytes() const {
    return static_cast<size_t>(size_) * size_ * 12 + static_cast<size_t>(bounceSize_) * bounceSize_ * (4 + 32 * 4 / 3) +
           static_cast<size_t>(layersSize_) * layersSize_ * 8;
  }
  PassTimer& timer() { return timer_; }

private:
  int size_;
  gl::Program program_, layersProgram_;
  gl::Texture distance_, depth_;
  int bounceSize_;
  gl::Texture bouncePosition_, bounceNormal_, bounceDepth_;
  int layersSize_;
  gl::Texture layers_;
  gl::Framebuffer fbo_, bounceFbo_, layersFbo_;
  bool cullsHiddenFaces_ = true;
  PassTimer timer_;
};

}  // namespace marble
