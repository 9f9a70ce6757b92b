#pragma once
// The uniforms of shaders/deferred_common.glsl (camera and light), set the same way for every
// deferred screen pass that includes it.
#include <string>

#include "marble/gl/program.h"
#include "marble/render/view_setup.h"
#include "marble/scene/scene.h"

namespace marble {

void setFrameUniforms(const gl::Program& program, const CameraMatrices& camera, const LightMatrices& lightM,
                      const Light& light, float lightTexelWorld);

// The define that makes the light's kind a constant of a program (LIGHT_DIRECTIONAL 0 or 1,
// shaders/light_geometry.glsl): the passes that ask for the light's vector and distance at every
// sample (lighting, post, the bounce's two gathers) keep one program per kind, and
// setFrameUniforms' u_light_directional then has no location there.
std::string lightKindDefine(bool directional);

}  // namespace marble
