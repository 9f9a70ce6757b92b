#pragma once
// The stage around the object (issue 19; shaders/stage.frag.glsl): the environment as the
// backdrop and a ground plane receiving the object's shadow and a soft contact shadow, drawn
// into the display image after the post pass where the camera sees no object. `marble` mode
// only, and only when the scene asks (render.backdrop, render.ground; both off by default and in
// every comparison scene, whose pictures are unchanged: the pass does not run for them).
#include "marble/gl/program_variants.h"
#include "marble/render/environment_map.h"
#include "marble/render/gpu_mesh.h"
#include "marble/render/light_depth_pass.h"
#include "marble/render/pass_timer.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

// Whether the scene shows a stage (the pass runs).
bool sceneHasStage(const Scene& scene);

class StagePass {
public:
  explicit StagePass(const ShaderLibrary& shaders);
  // The orthographic map of the object seen from below (its lowest surface above each floor
  // point) for the contact shadow: re-made when the mesh or the model transform changed.
  void updateBottomMap(const GpuMesh& mesh, const glm::mat4& model);
  void invalidateBottomMap() { bottomValid_ = false; }
  // targetFbo: the display image (attachment 0 is written; FXAA's luma in alpha when `lumaAlpha`).
  void run(const Scene& scene, const CameraMatrices& camera, const LightMatrices& light, float lightTexelWorld,
           const EnvironmentMap* environment, GLuint depth, GLuint lightShadow, float groundY, GLuint targetFbo,
           int width, int height, bool lumaAlpha);
  PassTimer& timer() { return timer_; }
  size_t bytes() const { return bottom_.bytes(); }

private:
  gl::ProgramVariants programs_;
  gl::VertexArray emptyVao_;
  LightDepthPass bottom_;  // a "light" from straight below, orthographic: distances are heights
  LightMatrices bottomMatrices_;
  bool bottomValid_ = false;
  glm::mat4 bottomModel_{1.0f};
  PassTimer timer_;
};

}  // namespace marble
