#pragma once
// Sets the u_pat_ uniforms declared by shaders/marble_pattern.glsl from a Material, with
// glProgramUniform* (no need to bind the program). Uniforms the compiler optimized out
// (location -1) are skipped silently.
#include "marble/scene/material.h"

namespace marble {

void applyPatternUniforms(unsigned int program, const Material& m);

}  // namespace marble
