// The `marble` mode's light at a surface point, split the way the passes need it: what enters
// the stone (lighting pass, then the subsurface blur) and what the surface reflects (post pass).
// Needs from the includer: marble_shading.glsl (BRDF pieces) and environment.glsl.
#include "principled_entry.glsl"

// Light the surface reflects (`marble` mode, linear HDR): GGX from the light, shadowed, with the
// dielectric's exact Fresnel factor (as Cycles' Principled BSDF), and the environment's blurred
// reflection weighted by the split-sum BRDF (Schlick-based: Karis's fit). E: the light's
// irradiance at normal incidence; visible: its PCF visibility; ior: the stone's index.
// footprint_a2: added to GGX's alpha^2 for the normal's spread over the pixel (0: none).
vec3 marble_reflected(vec3 N, vec3 V, vec3 L, vec3 E, float visible, float ior, float roughness, float footprint_a2,
                      float env_intensity) {
  float NoV = max(dot(N, V), 1e-4);
  float nl = max(dot(N, L), 0.0);
  vec3 H = normalize(V + L);
  float a_stone = max(roughness * roughness, 0.002);
  float a = sqrt(min(a_stone * a_stone + footprint_a2, 1.0));  // the lobe widened by the pixel's footprint
  float F = fresnel_dielectric(dot(H, V), ior);
  float D = footprint_filtered_distribution(max(dot(N, H), 0.0), a_stone * a_stone, a * a);
  vec3 r = E * (nl * visible * D * smith_ggx_visibility(NoV, nl, a) * F);
  if (env_intensity > 0.0)
    r += env_intensity * env_radiance(reflect(-V, N), roughness) * env_brdf_approx(f0_from_ior(ior), roughness, NoV);
  return r;
}

// Light that enters the stone through the surface here (irradiance / PI, before the albedo):
// from the light and from the environment, with the Principled coupling (principled_entry.glsl).
vec3 marble_surface_entering(vec3 N, vec3 L, vec3 E, float visible, float env_intensity) {
  float nl = max(dot(N, L), 0.0);
  vec3 e = E * nl * visible * principled_entry(nl) / PI;
  // The environment's light entering by the same rule, averaged over a uniform hemisphere:
  // 1 - 1/2 * int (1 - c)^5 2c dc = 1 - 1/42.
  if (env_intensity > 0.0) e += env_intensity * env_diffuse(N) * (41.0 / 42.0);
  return e;
}
