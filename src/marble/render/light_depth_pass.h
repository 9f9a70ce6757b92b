#pragma once
// Pass 1: the mesh seen from the light into a map of world-space distances (R32F) with its
// own depth buffer. Read by the lighting pass for thickness and shadows; beside it a reflective
// shadow map with mipmaps at an eighth of the size, drawn separately (light_depth.frag.glsl), for the
// `marble` mode's diffuse bounce. Its maps come at the full size (the constructor's) and, for
// interaction detail while the object or the light moves, at a reduced one (setMapSize); the
// accessors give the set the last run drew.
#include <optional>

#include "marble/gl/program.h"
#include "marble/render/face_culling.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/light_maps.h"
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
  // The size the next run draws its maps at (clamped to [1, fullSize()]): fullSize() uses the
  // full-size set; a smaller size a second set, made at its first use and kept while its size is
  // asked for (the full set is not touched meanwhile). The caller re-runs the pass after a change.
  void setMapSize(int size);
  // For tests: whether hidden faces are culled (on by default).
  void setCullsHiddenFaces(bool on) { cullsHiddenFaces_ = on; }
  GLuint distanceTexture() const { return maps().distance.id(); }
  GLuint depthTexture() const { return maps().depth.id(); }  // compare mode on, for sampler2DShadow
  // The reflective shadow map: world position x w, w (RGBA32F) and the unit normal with the
  // glossy emitters' grazing weight a (RGBA32F: a is an area, like w), mipmapped: a level's
  // texel is the w-weighted mean of the texels under it.
  GLuint bouncePositionTexture() const { return maps().bouncePosition.id(); }
  GLuint bounceNormalTexture() const { return maps().bounceNormal.id(); }
  // At a quarter of the size, the distance from the light to the nearest surface facing it and to
  // the nearest facing away (RG32F, nearest; kNoLayer where there is none): where the light enters
  // and leaves the first part it meets (light_layers.frag.glsl), for the hidden mirror image
  // (hidden_mirror.glsl), and for the bounce's visibility through the stone (bounce_through_stone.glsl).
  GLuint layersTexture() const { return maps().layers.id(); }
  static constexpr float kNoLayer = 1e30f;
  int size() const { return maps().size; }  // the maps in use (setMapSize)
  int fullSize() const { return full_.size; }
  int bounceSize() const { return maps().bounceSize; }  // the reflective shadow map's finest width
  int layersSize() const { return maps().layersSize; }  // the layers' width
  size_t bytes() const { return full_.bytes() + (reduced_ ? reduced_->bytes() : 0); }
  PassTimer& timer() { return timer_; }

private:
  gl::Program program_, layersProgram_;
  LightMaps full_;
  std::optional<LightMaps> reduced_;
  bool reducedInUse_ = false;
  const LightMaps& maps() const { return reducedInUse_ ? *reduced_ : full_; }
  LightMaps& maps() { return reducedInUse_ ? *reduced_ : full_; }
  bool cullsHiddenFaces_ = true;
  HiddenFaceDraw hiddenFaceDraw_;
  PassTimer timer_;
};

}  // namespace marble
