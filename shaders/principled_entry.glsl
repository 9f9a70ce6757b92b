// The Principled BSDF's entry weight, one place for it: the `marble` mode's direct light
// (marble_light.glsl) and the light-depth pass's reflective shadow map (light_depth.frag.glsl).
// How much of the light arriving at cosine cos_in enters the stone. The coupling is the Principled BSDF's, as Cycles
// 3.4 applies it to random-walk subsurface scattering (kernel/closure/bsdf_principled_diffuse.h,
// PRINCIPLED_DIFFUSE_LAMBERT_EXIT; Burley 2012, eq. 3): light enters with 1 - F_L / 2,
// F_L = (1 - cos)^5 (Schlick's weight without F0), so at grazing incidence half of it still enters;
// and Cycles leaves the viewer's side alone (its entry Fresnel at the camera's point,
// bsdf_principled_diffuse_compute_entry_fresnel, is never called), so nothing here depends on V.
// Nor is the specular layer taken out: the Principled BSDF adds it on top. Measured against
// Cycles, this moved the front- and side-lit exposure scale from 0.85-0.91 to 0.92-0.99
// (docs/quality.md). The retro-reflection lobe Cycles adds beside the walk is not light entering
// the stone: principled_retro below, reflected at the surface by the post pass.
// Schlick's weight without F0, (1 - cos)^5 with cos clamped to [0, 1] (Cycles' schlick_fresnel).
float schlick_weight(float cos_theta) {
  float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  float m2 = m * m;
  return m2 * m2 * m;
}

float principled_entry(float cos_in) {
  return 1.0 - 0.5 * schlick_weight(cos_in);
}

// The Principled BSDF's retro-reflection, which Cycles 3.4 adds beside the random walk as a diffuse
// closure of its own with the subsurface weight (kernel/closure/bssrdf.h, bssrdf_setup:
// PRINCIPLED_DIFFUSE_RETRO_REFLECTION, evaluated in bsdf_principled_diffuse.h; Burley 2012, eq. 4,
// with Cycles' RR = roughness (1 + L.V), which is Burley's 2 roughness cos^2 theta_d). Its BRDF is
// albedo / PI * N.L-weighted retro(N.L, N.V, L.V) below: light reflected at the surface point,
// not carried through the stone, so it is not blurred, and it depends on the view and the gloss,
// so the post pass adds it (marble_retro_reflected, marble_light.glsl). Largest where the camera
// grazes a lit face (F_V -> 1: RR, 0.15-0.3 of the Lambertian light at the scenes' roughness
// 0.15) and where the light grazes one (F_L); nearly 0 seen and lit head-on. Exact as Cycles'
// formula for any roughness; N.V is clamped to [0, 1] as Cycles' schlick_fresnel clamps 1 - N.V.
// Measured against Cycles: docs/quality.md, "Twenty-fourth session: the retro-reflection".
float principled_retro(float NoL, float NoV, float LoV, float roughness) {
  float FL = schlick_weight(NoL), FV = schlick_weight(NoV);
  float RR = roughness * (LoV + 1.0);
  return RR * (FL + FV + FL * FV * (RR - 1.0));
}
