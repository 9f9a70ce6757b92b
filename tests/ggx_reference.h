#pragma once
// The highlight marble's post pass draws, computed independently in double precision for the
// tests' expected values: the GGX distribution, the height-correlated Smith visibility and the
// dielectric's Fresnel reflectance from the refraction angle (not the shader's closed form, so
// that the tests check that form too), and the black stone that shows the highlight alone: one
// place for what the specular and valid-reflection tests integrate and render.
#include <algorithm>
#include <cmath>
#include "marble/scene/material.h"

namespace marble::test {

// Reflectance of a dielectric of index n for unpolarized light at cosine c (Fresnel's equations;
// Born & Wolf), from the refraction angle.
inline double fresnelFromRefractionAngle(double c, double n) {
  const double sinT = std::sqrt(1.0 - c * c) / n, cosT = std::sqrt(1.0 - sinT * sinT);
  const double rs = (c - n * cosT) / (c + n * cosT), rp = (n * c - cosT) / (n * c + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// Radiance of the highlight per unit of the light's radiance (irradiance pi at normal incidence):
// pi N.L D(N.H) Vis(N.L, N.V) F(H.V), GGX with a2 = alpha^2 = roughness^4. N.V is clamped at 1e-4
// as the shader does; the caller decides what N.L <= 0 means.
inline double ggxHighlight(double nl, double nv, double nh, double hv, double a2, double ior) {
  nv = std::max(nv, 1e-4);
  const double q = nh * nh * (a2 - 1.0) + 1.0, D = a2 / (M_PI * q * q);
  const double vis = 0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
  return M_PI * nl * D * vis * fresnelFromRefractionAngle(hv, ior);
}

// A black stone of index 1.5 that shows the highlight alone: no diffuse light, no transmission.
inline void showHighlightOnly(Material& m, float roughness) {
  m.base_color = m.vein_color = m.vein2_color = glm::vec3(0.0f);
  m.ior = 1.5f;
  m.roughness = roughness;
  m.translucency = 0.0f;
}

}  // namespace marble::test
