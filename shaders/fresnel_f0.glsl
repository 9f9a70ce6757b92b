// F0 of a dielectric from its index of refraction against air: ((n-1)/(n+1))^2 (marble_shading.glsl;
// alone for the bounce pass, which needs no more of it).
vec3 f0_from_ior(float ior) {
  float r = (ior - 1.0) / (ior + 1.0);
  return vec3(r * r);
}
