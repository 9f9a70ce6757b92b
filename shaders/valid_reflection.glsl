// Cycles' rule for a shading normal whose mirror reflection of the view would go below the
// surface (a smooth normal on a silhouette, where the interpolated normal faces away from the
// camera on a triangle that faces it): turn it toward the triangle's own normal until the view's
// reflection rises just above the triangle. Source: Cycles, kernel/closure/bsdf_util.h
// (`ensure_valid_reflection`, applied to the Principled BSDF's normal in svm/closure.h; the
// single-root solution as in Cycles 4's `ensure_valid_specular_reflection`); the formula is
// Cycles', this code marble's. Without it the GGX lobe at such pixels is evaluated at N.V ~ 0
// and a single silhouette pixel glints hundreds of times brighter than Cycles' (bunny-back's ear
// tip, docs/quality.md).

// True where the rule moves the normal, with the bent unit normal in `bent`; false (and `bent`
// untouched) where the view's reflection about n already rises t = min(0.9 Ng.I, 0.01) above
// the triangle. Unnormalized inputs: g, the triangle's normal facing the viewer; to_eye, toward
// the viewer; n, the shading normal on the viewer's side. The test costs one inverse square
// root and one division; the rest runs only on silhouettes (on a GPU: llvmpipe runs both sides
// of a branch).
bool valid_reflection_bend(vec3 g, vec3 to_eye, vec3 n, out vec3 bent) {
  float nn = dot(n, n);
  float inv_ig = inversesqrt(dot(to_eye, to_eye) * dot(g, g));
  float iz = dot(to_eye, g) * inv_ig;  // Ng.I of the unit vectors, >= 0
  float t = min(0.9 * iz, 0.01);
  // R.Ng of the unit vectors, R = 2 (n.I) n - I:
  float rz = (2.0 * dot(n, to_eye) * dot(n, g) / nn) * inv_ig - iz;
  if (!(nn > 0.0 && inv_ig < 1e30) || rz >= t) return false;
  // Frame: Ng as z, n in the x-z plane; the bent normal stays in that plane.
  vec3 ng = g * inversesqrt(dot(g, g));
  vec3 x = n - dot(n, ng) * ng;
  float x_len2 = dot(x, x);
  if (x_len2 <= 1e-12 * nn) {
    bent = ng;
    return true;
  }
  x *= inversesqrt(x_len2);
  float ix = dot(to_eye, x) * inversesqrt(dot(to_eye, to_eye));
  // 2 (sqrt(1 - z^2) ix + z iz) z - iz = t, squared: 4a z^4 - 2b z^2 + c = 0 with the terms
  // below. Of its two roots for z^2 the one that solves the unsquared equation is the larger
  // where ix < 0 and the smaller otherwise (Cycles 4).
  float a = max(ix * ix + iz * iz, 1e-12);
  float b = 2.0 * (a + iz * t);
  float c = (t + iz) * (t + iz);
  float root = sqrt(max(b * b - 4.0 * a * c, 0.0));
  float z2 = clamp(0.25 * (ix < 0.0 ? b + root : b - root) / a, 0.0, 1.0);
  bent = sqrt(1.0 - z2) * x + sqrt(z2) * ng;
  return true;
}
