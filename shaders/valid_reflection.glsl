// Cycles' rule for a shading normal whose mirror reflection of the view would go below the
// surface (a smooth normal on a silhouette, where the interpolated normal faces away from the
// camera on a triangle that faces it): turn it toward the triangle's own normal until the view's
// reflection rises just above the triangle. Source: Cycles, kernel/closure/bsdf_util.h
// (`ensure_valid_reflection`, applied to the Principled BSDF's normal in svm/closure.h; Cycles
// 4's `ensure_valid_specular_reflection`); the rule is Cycles', the closed form and code
// marble's. Without it the GGX lobe at such pixels is evaluated at N.V ~ 0 and a single
// silhouette pixel glints hundreds of times brighter than Cycles' (bunny-back's ear tip,
// docs/quality.md).

// True where the rule moves the normal, with the bent normal (not unit length) in `bent`; false
// (and `bent` untouched) where the view's reflection about n already rises
// t = min(0.9 Ng.I, 0.01) above the triangle. Unnormalized inputs: g, the triangle's normal
// facing the viewer; to_eye, toward the viewer; n, the shading normal on the viewer's side. The
// test costs two inverse square roots and one division; the bend (one square root) runs only on
// silhouettes on a GPU (llvmpipe runs both sides of a branch).
//
// The bend in closed form: the bent normal N' lies in the plane of Ng and n (x: n's part along
// the triangle, unit). Mirroring keeps the view's part in that plane, i_p = ix x + iz Ng, at its
// length rho = sqrt(ix^2 + iz^2), so the lifted reflection's part there is
// r_p = sqrt(rho^2 - t^2) x + t Ng, and N' is their half vector:
//   N' ~ i_p + r_p = (ix + sqrt(ix^2 + iz^2 - t^2)) x + (iz + t) Ng.
// It equals Cycles' root of 4a z^4 - 2b z^2 + c = 0 (`ensure_valid_specular_reflection`, the
// larger z^2 where ix < 0, the smaller otherwise) to 3e-12 over 128,000 random cases (numpy,
// double precision); the reflection stays on the side of Ng it had, as Cycles' does.
bool valid_reflection_bend(vec3 g, vec3 to_eye, vec3 n, out vec3 bent) {
  float inv_g = inversesqrt(dot(g, g));
  vec3 ng = g * inv_g;
  vec3 i = to_eye * inversesqrt(dot(to_eye, to_eye));
  float nn = dot(n, n);
  float iz = dot(i, ng);  // >= 0
  float t = min(0.9 * iz, 0.01);
  float n_ng = dot(n, ng);
  float rz = 2.0 * dot(n, i) * n_ng / nn - iz;  // R.Ng for the unit n, R = 2 (n.i) n - i
  if (!(nn > 0.0 && inv_g < 1e30) || rz >= t) return false;
  // x, unnormalized (length^2 x2): the formula above times x2, each term scaled alike.
  vec3 x = n - n_ng * ng;
  float x2 = dot(x, x);
  float ix_x = dot(i, x);  // ix times |x|
  bent = x2 <= 1e-12 * nn ? ng : (ix_x + sqrt(max(ix_x * ix_x + (iz * iz - t * t) * x2, 0.0))) * x + (iz + t) * x2 * ng;
  return true;
}
