// Where the screen-space mirror march (self_reflection.glsl) takes a visible face for its hit but the
// ray has met a face the camera cannot see, lit by the light: the tests that tell the two apart.
// Why: teapot-back's shoulder beside its silhouette and its body's left edge beside the handle arm
// mirror rays that run away from the camera toward the light behind the teapot (R.L 0.7-0.9); they
// pass behind the visible faces of the spout and the arm and meet those parts' sides toward the
// body, which the camera cannot see and the light lights directly. Cycles' glossy indirect light
// there (0.03-0.06, a one-pixel line) asks about 0.2 of radiance of the face; marble read the visible
// face in front (0.04-0.06, a quarter of Cycles' line after Fresnel). The march's own tolerance
// (a step plus two pixels, self_reflection.glsl) lets it call such a ray a hit, so the hit alone
// cannot tell them apart; two distances can (docs/quality.md, "Twenty-eighth session: ... the lit
// face behind the mirror hit"):
// - gap: how far the ray's point on the hit pixel (the march's refined point behind it) lies behind
//   the visible face, in view depth. On the mirror line's pixels 0.03-0.06 scene units; where the ray meets the visible face
//   itself 0.00-0.01 (the bisection's leftover step).
// - below: how far that point lies beyond the light's entry surface, along the light's ray (the
//   light's map, light_entry_at). On the line -0.01 ... 0.05; beside it, where the ray runs inside
//   a part the light does not reach directly, 0.1-0.2.
// Thresholds measured on teapot-back (SSIM 0.94666 on main dc79294), |below| < 4 / 6 / 8 light-map
// texels (0.0135 / 0.0203 / 0.0270 units there): gap > 0.02: 0.94841 / 0.94880 / 0.94865; gap > 0.03:
// 0.94824 / 0.94863 / 0.94855; gap > 0.04: 0.94788 / 0.94823 / 0.94827. A wider band (|below| < 0.05
// / 0.1 units, an earlier form of the test) takes faces the ray only passes near: 0.9475 / 0.9456.
// Kept: gap > 0.03, 6 texels, on the ten reference scenes mean +0.00015 (gap > 0.02: +0.00014),
// buddha-back -0.0004 the largest fall. Valid for scenes scaled as the reference scenes (the object
// normalized to the unit sphere): the gap is in scene units, not tied to the pixel.
#ifndef MIRROR_LIT_FACE_GLSL
#define MIRROR_LIT_FACE_GLSL
const float MIRROR_LIT_FACE_GAP = 0.03;     // scene units behind the visible face
const float MIRROR_LIT_FACE_TEXELS = 6.0;   // light-map texels from the light's entry surface

// Whether the ray's point on the hit pixel, gap behind the visible face, has passed behind it.
bool mirror_behind_visible_face(float gap) { return gap > MIRROR_LIT_FACE_GAP; }
// Whether that point, below beyond the light's entry surface (light_texel: the light map's texel in
// scene units), lies at the lit face.
bool mirror_at_light_entry(float below, float light_texel) { return abs(below) < MIRROR_LIT_FACE_TEXELS * light_texel; }
// Both: the ray meets a lit face hidden behind the visible one.
bool mirror_meets_lit_face(float gap, float below, float light_texel) {
  return mirror_behind_visible_face(gap) && mirror_at_light_entry(below, light_texel);
}
#endif
