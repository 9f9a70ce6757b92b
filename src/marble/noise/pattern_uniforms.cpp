#include "marble/noise/pattern_uniforms.h"

#include <epoxy/gl.h>

#include "marble/noise/marble_pattern.h"

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
  // vein model (issue 16); values as marble_pattern.cpp's toParams gives the C++ reference.
  const VeinUniformValues v = veinUniformValues(m);
  glProgramUniform1i(p, loc("u_pat_vein_model"), v.model);
  glProgramUniform3f(p, loc("u_pat_vein_spacing"), m.vein_spacing.x, m.vein_spacing.y, m.vein_spacing.z);
  glProgramUniform3f(p, loc("u_pat_vein_width"), m.vein_width.x, m.vein_width.y, m.vein_width.z);
  glProgramUniform3f(p, loc("u_pat_vein_density"), m.vein_density.x, m.vein_density.y, m.vein_density.z);
  glProgramUniform3f(p, loc("u_pat_vein_normal"), v.direction.x, v.direction.y, v.direction.z);
  glProgramUniform1f(p, loc("u_pat_vein_stretch"), m.vein_stretch);
  glProgramUniform1f(p, loc("u_pat_vein_warp"), m.vein_warp);
  glProgramUniform1f(p, loc("u_pat_vein_pinch"), m.vein_pinch);
  glProgramUniform1f(p, loc("u_pat_vein_softness"), m.vein_softness);
  glProgramUniform3f(p, loc("u_pat_vein3_color"), m.vein3_color.x, m.vein3_color.y, m.vein3_color.z);
  glProgramUniform3f(p, loc("u_pat_cloud_color"), m.cloud_color.x, m.cloud_color.y, m.cloud_color.z);
  glProgramUniform1f(p, loc("u_pat_cloud_amount"), m.cloud_amount);
  glProgramUniform1f(p, loc("u_pat_grain_amount"), m.grain_amount);
  glProgramUniform1f(p, loc("u_pat_fragment_tint"), m.fragment_tint);
}

}  // namespace marble
