// G-buffer encoding shared by the geometry pass (writer) and the screen passes (readers).

// Depth: the depth buffer's value z of a perspective projection with planes near_far, as the
// distance along the view axis (scene units).
float linear_depth(float z, vec2 near_far) {
  float n = near_far.x, f = near_far.y;
  return 2.0 * n * f / (f + n - (2.0 * z - 1.0) * (f - n));
}

// Normals: octahedral mapping into two signed-normalized 16-bit channels
// (Cigolle et al. 2014, "A Survey of Efficient Representations for Independent Unit Vectors";
// worst-case angular error about 0.002 degrees at 16 bits).
vec2 oct_wrap(vec2 v) {
  return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}
vec2 encode_normal(vec3 n) {
  n /= (abs(n.x) + abs(n.y) + abs(n.z));
  return n.z >= 0.0 ? n.xy : oct_wrap(n.xy);
}
vec3 decode_normal(vec2 e) {
  vec3 n = vec3(e.xy, 1.0 - abs(e.x) - abs(e.y));
  float t = max(-n.z, 0.0);
  n.x += n.x >= 0.0 ? -t : t;
  n.y += n.y >= 0.0 ? -t : t;
  return normalize(n);
}
