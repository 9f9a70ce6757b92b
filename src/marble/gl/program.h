#pragma once
// A linked GLSL program built from files of the ShaderLibrary. Uniform locations are
// looked up once and cached (no string lookups in the frame loop after the first).
#include <stdexcept>

#include <glm/glm.hpp>

#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "marble/gl/handles.h"
#include "marble/gl/shader_library.h"

namespace marble::gl {

struct ShaderStageSource {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
  std::string file;  // name in shaders/
};

// A uniform's location (-1 where the program has none) and GL type (GL_FLOAT, GL_FLOAT_VEC3, ...).
struct UniformSlot {
  GLint location = -1;
  GLenum type = 0;
};
// Looks each name up in `program` (a null name gets an empty slot).
std::vector<UniformSlot> lookUpUniforms(GLuint program, std::span<const char* const> names);

class Program {
public:
  Program() = default;
  // Compiles and links; throws ShaderError whose message names the shader file and line.
  Program(const ShaderLibrary& library, const std::vector<ShaderStageSource>& stages,
          const std::vector<std::string>& defines = {});

  GLuint id() const { return program_.id(); }
  GLint location(const char* name) const;

  void set(const char* name, float v) const { glProgramUniform1f(id(), location(name), v); }
  void set(const char* name, int v) const { glProgramUniform1i(id(), location(name), v); }
  void set(const char* name, const glm::vec2& v) const { glProgramUniform2f(id(), location(name), v.x, v.y); }
  void set(const char* name, const glm::vec3& v) const { glProgramUniform3f(id(), location(name), v.x, v.y, v.z); }
  void set(const char* name, const glm::vec4& v) const {
    glProgramUniform4f(id(), location(name), v.x, v.y, v.z, v.w);
  }
  void set(const char* name, const glm::mat4& m) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, &m[0][0]);
  }
  void set(const char* name, const glm::mat3& m) const {
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, &m[0][0]);
  }

  // A fixed list of uniforms (the material parameters', render/material_uniforms.h) looked up
  // once for this program. `names` must be the same array on every call.
  const std::vector<UniformSlot>& uniformTable(std::span<const char* const> names) const;

private:
  ProgramId program_;
  mutable const char* const* tableNames_ = nullptr;
  mutable std::vector<UniformSlot> table_;
  // Looked up by string_view (transparent hash): a name longer than the small-string buffer
  // would otherwise allocate a std::string on every set() of every frame.
  struct NameHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  mutable std::unordered_map<std::string, GLint, NameHash, std::equal_to<>> locations_;
};

class ShaderError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace marble::gl
