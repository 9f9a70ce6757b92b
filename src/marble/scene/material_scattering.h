#pragma once
// The stone's scattering given as Blender's Principled BSDF gives it (issue 15): `base_color` is
// the subsurface albedo and `subsurface_radius_mm` the mean free path per channel, exactly as
// Cycles' RANDOM_WALK subsurface method reads them (Blender 3.4.1: kernel/closure/bssrdf.h
// bssrdf_setup_radius, kernel/integrator/subsurface_random_walk.h subsurface_random_walk_remap,
// anisotropy 0). From them Cycles walks a volume with extinction sigma_t and single-scattering
// albedo alpha; marble's advanced form, sigma_a_mm and sigma_s_mm, is that volume:
//   sigma_s = alpha sigma_t, sigma_a = (1 - alpha) sigma_t (sigma_s' = sigma_s: isotropic walk).
#include <glm/glm.hpp>

#include "marble/scene/material.h"

namespace marble {

// Jensen et al. 2001's diffuse reflectance of a semi-infinite medium, the dipole with Cycles'
// boundary term: Rd(a') = a'/2 (1 + exp(-4/3 A sqrt(3 (1 - a')))) exp(-sqrt(3 (1 - a'))), with
// A = (1 + F_dr) / (1 - F_dr) and F_dr Egan & Hilgeman's fit for the relative index `ior`.
float dipoleReflectance(float alphaPrime, float ior);

// Cycles' inversion of Rd: the reduced albedo a' with Rd(a') = albedo, by its 12 bisection steps
// on [0, 1] (0 below 1e-4, 0.999999 from 0.995 up), so it is Cycles' number to the last bit it
// resolves (2^-12), not a more exact root.
float cyclesAlphaPrime(float albedo, float ior);

// Cycles' single-scattering albedo for a multiple-scattering albedo (Chiang et al. 2016's
// inversion, in Wrenninge et al. 2017's fit with anisotropy g = 0), clamped as Cycles does to
// [0.2, 0.999999] (below 0.2, i.e. albedo < 0.05, Cycles also scales the path's weight; marble
// cannot and does not).
float cyclesSingleScatteringAlbedo(float albedo);

struct ScatteringCoefficients {
  glm::vec3 sigma_a_mm, sigma_s_mm;  // per mm
};

// Cycles' RANDOM_WALK volume for albedo and radius (both per channel; radius in mm, > 0) at `ior`
// (clamped to [1.01, 3.8] as Cycles clamps Subsurface IOR): the radius is first scaled by
// sqrt(3 (1 - a')) (bssrdf_setup_radius), then sigma_t = 1 / radius.
ScatteringCoefficients coefficientsFromRadius(glm::vec3 albedo, glm::vec3 radiusMm, float ior);

// In the radius form (m.scattering == Radius), sets m.sigma_a_mm and m.sigma_s_mm from
// m.base_color, m.subsurface_radius_mm and m.ior; in the coefficient form, leaves m as it is.
// Every path that changes a material (files, --set, the viewer) calls it, so sigma_a_mm and
// sigma_s_mm always hold what the renderer uses.
void resolveScattering(Material& m);

// The diffusion's effective attenuation sigma_tr = sqrt(3 sigma_a (sigma_a + sigma_s)) per mm
// (Jensen et al. 2001, sec. 2.4; sigma_s' = sigma_s, isotropic), averaged over the channels:
// how fast the light that leaves the surface thins out with depth. The vein models' "seen
// through the polish" depth weight (pattern_core.glsl) in the `marble` mode.
float diffusionAttenuationMm(const Material& m);

}  // namespace marble
