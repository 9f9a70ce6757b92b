// The `marble` mode's light at a surface point, split the way the passes need it: what enters
// the stone (lighting pass, then the subsurface blur) and what the surface reflects (post pass).
// Needs from the includer: marble_shading.glsl (BRDF pieces) and environment.glsl.
#include "principled_entry.glsl"

// Light the surface reflects (`marble` mode, linear HDR): GGX from the light, shadowed, with the
// dielectric's exact Fresnel factor (as Cycles' Principled BSDF), and the environment's blurred
// reflection weighted by the split-sum BRDF (Schlick-based: Karis's fit). E: the light's
// irradiance at normal incidence; visible: its PCF visibility; ior: the stone's index.
// bx, ax, by, ay: the normal's change to the pixel's neighbours before and after it along x and y,
// less the half vector's (half_vector_step, post.frag.glsl; 0: a point sample); the light's lobe is integrated
// over the pixel's normals (footprint_mean_distribution), N.L, N.V and Smith's shadowing taken at
// the centroid of the lobe's mass within the footprint.
vec3 marble_reflected(vec3 N, vec3 V, vec3 L, vec3 E, float visible, float ior, float roughness, vec3 bx, vec3 ax, vec3 by,
                      vec3 ay, float env_intensity) {
  vec3 H = normalize(V + L);
  float a_stone = max(roughness * roughness, 0.002);
  vec3 N_lobe;
  float D = footprint_mean_distribution(N, H, bx, ax, by, ay, a_stone, N_lobe);
  float NoV = max(dot(N_lobe, V), 1e-4);
  float nl = max(dot(N_lobe, L), 0.0);
  float F = fresnel_dielectric(dot(H, V), ior);
  vec3 r = E * (nl * visible * D * smith_ggx_visibility(NoV, nl, a_stone) * F);
  if (env_intensity > 0.0)
    r += env_intensity * env_radiance(reflect(-V, N), roughness) * env_brdf_approx(f0_from_ior(ior), roughness, max(dot(N, V), 1e-4));
  return r;
}

// The light's retro-reflection (principled_retro: Cycles' Principled lobe beside the walk), per unit
// of u_light_radiance and of the albedo, which the post pass multiplies it by; reflected at the
// surface point, so not blurred. falloff: light_falloff at P (the irradiance at normal incidence per
// unit radiance); visible: the light's visibility, as the highlight's. Not modelled: the lobe for
// the environment's light and for the bounce (the light arriving from the stone's other parts),
// which enter the stone as diffuse light only (references: no environment; the bounce under a
// quarter of the shaded side's light, the lobe under 0.3 of it).
float marble_retro_reflected(vec3 N, vec3 V, vec3 L, float falloff, float visible, float roughness) {
  float nl = max(dot(N, L), 0.0);
  return falloff * nl * visible * principled_retro(nl, dot(N, V), dot(L, V), roughness) / PI;
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
