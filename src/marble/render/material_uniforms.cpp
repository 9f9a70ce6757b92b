#include "marble/render/material_uniforms.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "marble/scene/material_params.h"

namespace marble {

std::span<const char* const> materialUniformNames() {
  static const std::vector<const char*> names = [] {
    std::vector<const char*> n;
    for (const auto& p : materialParams()) n.push_back(p.uniform);
    return n;
  }();
  return names;
}

void uploadMaterialUniforms(GLuint program, std::span<const gl::UniformSlot> slots, const Material& m) {
  const auto params = materialParams();
  for (size_t i = 0; i < slots.size() && i < params.size(); ++i) {
    const gl::UniformSlot& slot = slots[i];
    if (slot.location < 0) continue;
    const ParamDesc& p = params[i];
    const ParamValue v = p.uniformValue ? p.uniformValue(m) : p.get(m);
    // The GLSL type decides the call; the parameter's value converts to it exactly (a whole
    // number below 2^24 as a float, an enum as its integer).
    if (const auto* f = std::get_if<float>(&v); f && slot.type == GL_FLOAT) {
      glProgramUniform1f(program, slot.location, *f);
    } else if (const auto* c = std::get_if<glm::vec3>(&v); c && slot.type == GL_FLOAT_VEC3) {
      glProgramUniform3f(program, slot.location, c->x, c->y, c->z);
    } else if (const auto* n = std::get_if<long long>(&v)) {
      if (slot.type == GL_INT) glProgramUniform1i(program, slot.location, static_cast<GLint>(*n));
      else if (slot.type == GL_UNSIGNED_INT) glProgramUniform1ui(program, slot.location, static_cast<GLuint>(*n));
      else if (slot.type == GL_FLOAT) glProgramUniform1f(program, slot.location, static_cast<float>(*n));
      else throw std::logic_error(std::string("material uniform ") + p.uniform + ": GLSL type cannot hold " + p.key);
    } else {
      throw std::logic_error(std::string("material uniform ") + p.uniform + ": GLSL type cannot hold " + p.key);
    }
  }
}

}  // namespace marble
