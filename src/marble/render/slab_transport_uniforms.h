#pragma once
// The random walk's slab transport table (marble::SlabTransport) as shaders/slab_transport.glsl
// reads it: cut from the walk's table again only when the material's coefficients change, not each
// time the camera or the light moves. The lighting pass (the transmission) and the bounce pass (the
// emitters on the far side of the light's first part) each hold one, so both read the same table.
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "marble/gl/program.h"
#include "marble/scene/slab_transport.h"

namespace marble {

class SlabTransportUniforms {
public:
  // Sets u_slab_ln_t, u_slab_tau_max and u_slab_sigma_t_mm on the program for the material.
  void upload(const gl::Program& program, const Material& m);

private:
  SlabTransport slab_;
  std::optional<std::pair<glm::vec3, glm::vec3>> for_;  // (sigma_a_mm, sigma_s_mm) slab_ was cut for
};

}  // namespace marble
