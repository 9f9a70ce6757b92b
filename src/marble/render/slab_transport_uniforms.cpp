#include "marble/render/slab_transport_uniforms.h"

namespace marble {

void SlabTransportUniforms::upload(const gl::Program& program, const Material& m) {
  // Derived from sigma_a_mm, sigma_s_mm: not parameters of their own.
  if (!for_ || for_->first != m.sigma_a_mm || for_->second != m.sigma_s_mm) {
    slab_ = slabTransportFor(m);
    for_ = std::pair(m.sigma_a_mm, m.sigma_s_mm);
  }
  glProgramUniform3fv(program.id(), program.location("u_slab_ln_t"), kSlabTransportNodes, &slab_.lnT[0].x);
  program.set("u_slab_tau_max", slab_.tauMax);
  program.set("u_slab_sigma_t_mm", slab_.sigmaTMm);
}

}  // namespace marble
