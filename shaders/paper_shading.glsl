// The shading models of the paper and its comparisons. Each cites its source.

const float PI = 3.14159265358979;

// Subsurface transmittance, paper §3.2 after GPU Gems 1 ch. 16 (Green 2004):
// sss = exp(-sigma_t * s), s = distance the light travelled inside the object.
// k_sss blends from no effect (0) to the full term (1).
vec3 paper_subsurface(vec3 thickness_sigma_t, float k_sss) {
  return mix(vec3(1.0), exp(-thickness_sigma_t), k_sss);
}

// Fresnel-Schlick, paper §3.3 (Schlick 1994; LearnOpenGL "PBR/Theory"):
// F0 = mix(0.04, diffuse, metalness); F = F0 + (1 - F0)(1 - cos)^5.
// The paper takes cos = H.N. The standard form (Schlick; Walter et al. 2007) takes H.V:
// Fresnel depends on the angle between the incoming light and the microfacet normal H, and
// H.V = H.L. H.N is the microfacet *distribution* angle and makes F peak where the
// highlight is, not at grazing angles, so H.V is our default and H.N is kept for the paper.
vec3 paper_schlick(vec3 diffuse, float metalness, vec3 N, vec3 V, vec3 L, int use_hn) {
  vec3 H = normalize(V + L);
  vec3 F0 = mix(vec3(0.04), diffuse, metalness);
  float c = clamp(use_hn == 1 ? dot(H, N) : dot(H, V), 0.0, 1.0);
  return F0 + (1.0 - F0) * pow(1.0 - c, 5.0);
}

// Phong (1975), as in LearnOpenGL "Basic Lighting" (paper ref. [1], its Figure 4):
// ambient + diffuse N.L + specular (R.V)^shininess.
vec3 phong(vec3 albedo, vec3 N, vec3 V, vec3 L, vec3 light, float shininess) {
  float diff = max(dot(N, L), 0.0);
  vec3 R = reflect(-L, N);
  float spec = diff > 0.0 ? pow(max(dot(R, V), 0.0), shininess) : 0.0;
  return albedo * (0.15 + diff * light) + 0.5 * spec * light;
}

// Oren-Nayar (1994) qualitative model, paper's Figure 9:
// L = albedo/pi * E * cos(theta_i) * (A + B max(0, cos(phi_i - phi_r)) sin(alpha) tan(beta)),
// A = 1 - 0.5 s^2/(s^2+0.33), B = 0.45 s^2/(s^2+0.09). Multiplied by pi so a white
// Lambertian surface facing a unit light shows 1.0, like the Phong mode.
vec3 oren_nayar(vec3 albedo, vec3 N, vec3 V, vec3 L, vec3 light, float sigma) {
  float s2 = sigma * sigma;
  float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
  float B = 0.45 * s2 / (s2 + 0.09);
  float NL = max(dot(N, L), 0.0);
  float NV = max(dot(N, V), 0.0);
  float theta_i = acos(NL), theta_r = acos(NV);
  vec3 Lp = normalize(L - N * NL + 1e-6 * N.yzx);
  vec3 Vp = normalize(V - N * NV + 1e-6 * N.yzx);
  float cos_phi = max(dot(Lp, Vp), 0.0);
  float alpha = max(theta_i, theta_r), beta = min(theta_i, theta_r);
  return albedo * (0.15 + light * NL * (A + B * cos_phi * sin(alpha) * tan(beta)));
}
