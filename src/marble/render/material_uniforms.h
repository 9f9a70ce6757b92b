#pragma once
// The material's uniforms, from the parameters' descriptions (scene/material_params.h): every
// parameter with a uniform that the program declares is set, with glProgramUniform* (no need
// to bind the program). Locations are looked up once per program (gl::Program::uniformTable);
// a uniform the compiler optimized out is skipped.
#include <span>

#include "marble/gl/program.h"
#include "marble/scene/material.h"

namespace marble {

// Each parameter's uniform name (nullptr where it has none), in materialParams() order.
std::span<const char* const> materialUniformNames();

// Sets the uniforms in `slots` (looked up for materialUniformNames()) in `program`.
// Throws std::logic_error when a uniform's GLSL type cannot hold its parameter.
void uploadMaterialUniforms(GLuint program, std::span<const gl::UniformSlot> slots, const Material& m);

inline void uploadMaterialUniforms(const gl::Program& p, const Material& m) {
  uploadMaterialUniforms(p.id(), p.uniformTable(materialUniformNames()), m);
}

}  // namespace marble
