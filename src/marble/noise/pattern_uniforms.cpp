#include "marble/noise/pattern_uniforms.h"

#include <epoxy/gl.h>

namespace marble {

void applyPatternUniforms(unsigned int program, const Material& m) {
  const GLuint p = program;
  auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
  // Enum values match PAT_BASIS_* / PAT_MAP_* in shaders/pattern_core.glsl.
  const int basis = m.basis == NoiseBasis::Perlin ? 1 : 0;
  const int mapping = m.mapping == PatternMapping::Planar ? 0 : m.mapping == PatternMapping::Triplanar ? 1 : 2;
  glProgramUniform1ui(p, loc("u_pat_seed"), m.seed);
  glProgramUniform1f(p, loc("u_pat_resolution"), static_cast<float>(m.resolution));
  glProgramUniform1i(p, loc("u_pat_basis"), basis);
  glProgramUniform1i(p, loc("u_pat_mapping"), mapping);
  glProgramUniform3f(p, loc("u_pat_period"), m.x_period, m.y_period, m.z_period);
  glProgramUniform1f(p, loc("u_pat_turb_power"), m.turb_power);
  glProgramUniform1f(p, loc("u_pat_turb_size"), m.turb_size);
  glProgramUniform1f(p, loc("u_pat_scale"), m.pattern_scale);
  glProgramUniform1f(p, loc("u_pat_vein_sharpness"), m.vein_sharpness);
  glProgramUniform1f(p, loc("u_pat_vein2_amount"), m.vein2_amount);
  glProgramUniform3f(p, loc("u_pat_base_color"), m.base_color.x, m.base_color.y, m.base_color.z);
  glProgramUniform3f(p, loc("u_pat_vein_color"), m.vein_color.x, m.vein_color.y, m.vein_color.z);
  glProgramUniform3f(p, loc("u_pat_vein2_color"), m.vein2_color.x, m.vein2_color.y, m.vein2_color.z);
}

}  // namespace marble
