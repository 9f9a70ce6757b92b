// The random walk's slab transport (the transmission's, lighting.frag.glsl; and since session 20
// the bounce's emitters on the far side of the light's first part, bounce_exits.frag.glsl): one
// place for the table's uniforms and its read. LightingPass and BouncePass upload the same table
// (slab_transport_uniforms.h).
// The random walk's slab transport cut to the material (marble::SlabTransport): ln(T / R_inf) per
// channel at optical thicknesses tau_i = u_slab_tau_max (i / (SLAB_NODES - 1))^2, tau = sigma_t s.
const int SLAB_NODES = 40;  // marble::kSlabTransportNodes
uniform vec3 u_slab_ln_t[SLAB_NODES];
uniform float u_slab_tau_max;
uniform vec3 u_slab_sigma_t_mm;  // extinction sigma_a + sigma_s per mm

// Light carried through s mm of stone, relative to what the same stone reflects: Cycles' random
// walk through a slab (isotropic scattering, no reflection inside the boundary, dropped after 256
// flights), tabulated by tools/slab_walk_table.py (marble::slabTransportFor) and read here
// linearly in ln T between nodes, 0 beyond the table (tau > 64: under 1e-5 of the reflected light;
// the walk's cap makes it fall faster than any exponential there). Divided by R_inf because the
// albedo multiplies the diffuse light later (post pass). Against Cycles' own slab renders of the
// issue's stone it agrees within their noise at 2-20 mm; the dipole it replaced let 1.3-1.5x too
// much red through (docs/quality.md, "Transmission from a random walk").
vec3 slab_transport(float s_mm) {
  vec3 tau = u_slab_sigma_t_mm * s_mm;
  vec3 x = sqrt(clamp(tau / u_slab_tau_max, 0.0, 1.0)) * float(SLAB_NODES - 1);
  ivec3 i = min(ivec3(x), ivec3(SLAB_NODES - 2));
  vec3 f = x - vec3(i);
  vec3 lo = vec3(u_slab_ln_t[i.r].r, u_slab_ln_t[i.g].g, u_slab_ln_t[i.b].b);
  vec3 hi = vec3(u_slab_ln_t[i.r + 1].r, u_slab_ln_t[i.g + 1].g, u_slab_ln_t[i.b + 1].b);
  return exp(mix(lo, hi, f)) * vec3(lessThan(tau, vec3(u_slab_tau_max)));
}
