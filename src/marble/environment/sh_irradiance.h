#pragma once
// Diffuse light from an environment as 9 spherical-harmonic coefficients (Ramamoorthi and
// Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps"): project the
// radiance onto the real SH basis up to l = 2 (their eq. 10, with each texel weighted by its
// solid angle), then the irradiance E(n) for any normal is a quadratic polynomial in n
// (their eq. 13). Average error below 3% for any lighting, since the clamped cosine kernel
// has almost nothing above l = 2.
#include <array>

#include <glm/glm.hpp>

#include "marble/core/image.h"

namespace marble {

// Coefficients L_lm per RGB channel, in the paper's order:
// L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (basis in world x, y, z as they are).
using ShCoefficients = std::array<glm::vec3, 9>;

ShCoefficients projectSh9(const ImageRGBF& equirect);

// Irradiance E(n) (W/m^2 per unit radiance; a constant environment L gives pi L), eq. 13.
glm::vec3 shIrradiance(const ShCoefficients& sh, const glm::vec3& n);

// The same polynomial, divided by pi and regrouped for the shader (shaders/environment.glsl,
// env_diffuse): E(n)/pi = k0 + k1 x + k2 y + k3 z + k4 xy + k5 yz + k6 xz + k7 z^2 + k8 (x^2 - y^2).
std::array<glm::vec3, 9> shDiffuseTerms(const ShCoefficients& sh);

}  // namespace marble
