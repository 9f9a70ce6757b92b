// Cycles' rule for a shading normal whose mirror reflection of the view would go below the
// surface (a smooth normal on a silhouette, where the interpolated normal faces away from the
// camera on a triangle that faces it): turn it toward the triangle's own normal until the view's
// reflection rises just above the triangle. Source: Cycles 3.4, kernel/closure/bsdf_util.h
// (`ensure_valid_reflection`, applied to the Principled BSDF's normal in svm/closure.h); the
// formula is Cycles', this code marble's. Without it the GGX lobe at such pixels is evaluated at
// N.V ~ 0 and a single silhouette pixel glints tens of times brighter than Cycles' (bunny-back's
// ear tip, docs/quality.md).
//   ng: the triangle's normal, unit, facing the viewer; i: unit vector toward the viewer;
//   n: the unit shading normal, facing the viewer's side.
vec3 valid_reflection_normal(vec3 ng, vec3 i, vec3 n) {
  float iz = dot(ng, i);
  // The reflection may be as shallow as the view, but no more than 0.01 above the surface.
  float t = min(0.9 * iz, 0.01);
  vec3 r = 2.0 * dot(n, i) * n - i;
  if (dot(ng, r) >= t) return n;
  // Frame: ng as z, n in the x-z plane; the bent normal stays in that plane.
  vec3 x = n - dot(n, ng) * ng;
  float x_len2 = dot(x, x);
  if (x_len2 < 1e-12) return ng;
  x *= inversesqrt(x_len2);
  float ix = dot(i, x);
  // Solve 2 (sqrt(1 - z^2) ix + z iz) z - iz = t for z^2 (two non-negative roots).
  float a = ix * ix + iz * iz;
  float b = sqrt(max(ix * ix * (a - t * t), 0.0));
  float c = iz * t + a;
  float z1 = 0.5 * (c + b) / a, z2 = 0.5 * (c - b) / a;
  bool valid1 = z1 > 1e-5 && z1 <= 1.0 + 1e-5;
  bool valid2 = z2 > 1e-5 && z2 <= 1.0 + 1e-5;
  vec2 bent;  // (x, z) of the bent normal
  if (valid1 && valid2) {
    vec2 n1 = vec2(sqrt(max(1.0 - z1, 0.0)), sqrt(z1));
    vec2 n2 = vec2(sqrt(max(1.0 - z2, 0.0)), sqrt(z2));
    // Squaring admitted roots whose reflection is below the surface; keep one above it, the
    // shallower if both are (the closer to n).
    float r1 = 2.0 * (n1.x * ix + n1.y * iz) * n1.y - iz;
    float r2 = 2.0 * (n2.x * ix + n2.y * iz) * n2.y - iz;
    bent = (r1 >= 1e-5 && r2 >= 1e-5) ? (r1 < r2 ? n1 : n2) : (r1 > r2 ? n1 : n2);
  } else if (valid1 || valid2) {
    float z2_kept = valid1 ? z1 : z2;
    bent = vec2(sqrt(max(1.0 - z2_kept, 0.0)), sqrt(z2_kept));
  } else {
    return ng;
  }
  return bent.x * x + bent.y * ng;
}
