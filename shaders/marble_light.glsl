// The `marble` mode's light at a surface point, split the way the passes need it: what enters
// the stone (lighting pass, then the subsurface blur) and what the surface reflects (post pass).
// Needs from the includer: marble_shading.glsl (BRDF pieces) and environment.glsl.

// Light the surface reflects (`marble` mode, linear HDR): GGX from the light, shadowed, and
// the environment's blurred reflection weighted by the split-sum BRDF. E: the light's
// irradiance at normal incidence; visible: its PCF visibility.
vec3 marble_reflected(vec3 N, vec3 V, vec3 L, vec3 E, float visible, vec3 F0, float roughness, float env_intensity) {
  float NoV = max(dot(N, V), 1e-4);
  float nl = max(dot(N, L), 0.0);
  vec3 H = normalize(V + L);
  float a = max(roughness * roughness, 0.002);
  vec3 F = fresnel_schlick(F0, dot(H, V));
  vec3 r = E * nl * visible * ggx_distribution(max(dot(N, H), 0.0), a) * smith_ggx_visibility(NoV, nl, a) * F;
  if (env_intensity > 0.0)
    r += env_intensity * env_radiance(reflect(-V, N), roughness) * env_brdf_approx(F0, roughness, NoV);
  return r;
}

// Light that enters the stone through the surface here (irradiance / PI, before the albedo):
// from the light and from the environment. The coupling is the Principled BSDF's, as Cycles
// 3.4 applies it to random-walk subsurface scattering (kernel/closure/bsdf_principled_diffuse.h,
// PRINCIPLED_DIFFUSE_LAMBERT_EXIT; Burley 2012, eq. 3): light enters with 1 - F_L / 2,
// F_L = (1 - cos)^5 (Schlick's weight without F0), so at grazing incidence half of it still enters;
// and Cycles leaves the viewer's side alone (its entry Fresnel at the camera's point,
// bsdf_principled_diffuse_compute_entry_fresnel, is never called), so nothing here depends on V.
// Nor is the specular layer taken out: the Principled BSDF adds it on top. Measured against
// Cycles, this moved the front- and side-lit exposure scale from 0.85-0.91 to 0.92-0.99
// (docs/quality.md). The retro-reflection lobe (RR = roughness (1 + L.V)) is not modelled: it
// would tie the light entering to the gloss (a roughness change would re-run the blur) and gained
// under 0.003 in SSIM and relative RMSE on the reference scenes.
float principled_entry(float cos_in) {
  float m = 1.0 - clamp(cos_in, 0.0, 1.0);
  float m2 = m * m;
  return 1.0 - 0.5 * (m2 * m2 * m);
}

vec3 marble_surface_entering(vec3 N, vec3 L, vec3 E, float visible, float env_intensity) {
  float nl = max(dot(N, L), 0.0);
  vec3 e = E * nl * visible * principled_entry(nl) / PI;
  // The environment's light entering by the same rule, averaged over a uniform hemisphere:
  // 1 - 1/2 * int (1 - c)^5 2c dc = 1 - 1/42.
  if (env_intensity > 0.0) e += env_intensity * env_diffuse(N) * (41.0 / 42.0);
  return e;
}
