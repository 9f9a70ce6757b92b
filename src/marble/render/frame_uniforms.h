#pragma once
// The uniforms of shaders/deferred_common.glsl (camera and light), set the same way for every
// deferred screen pass that includes it.
#include "marble/gl/program.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

void setFrameUniforms(const gl::Program& program, const CameraMatrices& camera, const LightMatrices& lightM,
                      const Light& light, float lightTexelWorld);

}  // namespace marble
