#pragma once
// The `marble` mode's transmission through the stone (issue 15): the light a random walk carries
// through a slab, as Blender Cycles' RANDOM_WALK subsurface computes it, relative to what the same
// stone reflects. Tabulated offline by tools/slab_walk_table.py (slab_walk_table.inc; the walk and
// its sources are stated there) over the slab's optical thickness tau = sigma_t * s and the
// single-scattering albedo; here the table is cut, per colour channel, to the material's albedo,
// and shaders/lighting.frag.glsl (slab_transport) reads it at tau.
//
// It replaces the dipole's slab transport (Jensen et al. 2001's R_d over a plane s away): that
// diffusion model assumes a Fresnel boundary Cycles' walk does not have and no cap on the walk's
// length, and let 1.3-1.5x too much red light through 2-20 mm (and too little blue at 10 mm)
// against Cycles' own slab renders (docs/quality.md, "Transmission from a random walk").
#include <array>

#include <glm/glm.hpp>

#include "marble/scene/material.h"

namespace marble {

constexpr int kSlabTransportNodes = 40;

struct SlabTransport {
  // ln(T / R_inf) per channel at the nodes tau_i = tauMax (i / (kSlabTransportNodes - 1))^2.
  std::array<glm::vec3, kSlabTransportNodes> lnT{};
  float tauMax = 0.0f;
  glm::vec3 sigmaTMm{0.0f};  // the extinction sigma_a + sigma_s per mm: tau = sigma_t * s
};

// The table for the material's coefficients (sigma_a_mm, sigma_s_mm: isotropic, so the walk's
// single-scattering albedo is sigma_s / (sigma_a + sigma_s)), linear in -log10(1 - alpha)
// between the table's rows and clamped to its range (alpha 0.21 to 0.999999).
SlabTransport slabTransportFor(const Material& m);

// T(s) / R_inf per channel for s millimetres of the material, as the shader computes it (linear
// in ln between nodes, 0 beyond tauMax): for tests and tools.
glm::vec3 slabTransportAt(const SlabTransport& t, float sMm);

}  // namespace marble
