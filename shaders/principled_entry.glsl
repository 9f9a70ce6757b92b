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
// (docs/quality.md). The retro-reflection lobe (RR = roughness (1 + L.V)) is not modelled: it
// would tie the light entering to the gloss (a roughness change would re-run the blur) and gained
// under 0.003 in SSIM and relative RMSE on the reference scenes.
float principled_entry(float cos_in) {
  float m = 1.0 - clamp(cos_in, 0.0, 1.0);
  float m2 = m * m;
  return 1.0 - 0.5 * (m2 * m2 * m);
}
