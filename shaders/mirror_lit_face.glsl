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

// The lit face's light spread by the walk (hidden_mirror.glsl, hidden_lit_face_behind). A face the
// camera sees gets the light entering around it through the subsurface blur; the hidden face has no
// pixels to blur, and its own texel's irradiance alone is the walk's light only where the irradiance
// is the same all around it. The walk (subsurface_profile.h, walkSquareShare) leaves half its light
// within about a millimetre of the entry (in the issue's stone, a square of half-width 1.2 / 0.84 /
// 0.73 mm per channel) and the other half farther out, and teapot-back's hidden faces (the spout's
// and the handle arm's sides toward the body, lit at cos 0.35-0.55) lie within a few millimetres of
// their parts' backs, lit head-on (cos 0.6-0.9 in a light-space ring 3-6 mm out): so the face's own
// coupling (cos x principled_entry) stands for the inner half, and a ring of
// LIT_FACE_RING_TAPS taps in the light's map for the outer half, at the outer half's median radius
// (the walk's 3/4 radius, walkRingRadiusMm: 2.06 mm in the issue's stone). The taps are uniform in
// the light's map, not over the surface: a tap on a face tilted from the light covers 1 / cos of its
// area, at a distance about 1 / cos of the ring's radius, where the walk's near-field density falls
// about as 1 / r; the two cancel, so a light-map tap weighs about as its surface does. A tap counts
// where its entry lies within two ring radii of the face's along the light (the face's part); the
// others (no stone in the light's map, or a nearer part) are left out and the weights summed are
// normalized, as the screen blur leaves out and normalizes its taps on other surfaces
// (subsurface_blur.frag.glsl). Approximations: one ring for the whole outer half (the irradiance
// taken as varying linearly over it), one radius for the three channels (their luminance-weighted
// mean), the 1 / r near field for the tilt's cancellation, the outer half's weight exactly half.
// Counting the left-out taps as unlit surface instead (0) lost 0.0002 on teapot-back against main.
// Measured: docs/quality.md, "Twenty-ninth session: the lit face's light spread by the walk".
const int LIT_FACE_RING_TAPS = 4;
const float LIT_FACE_OWN_WEIGHT = float(LIT_FACE_RING_TAPS);  // the inner half: the ring's taps together
// The ring's directions, along the light map's axes (constants: no cos and sin per tap). Four taps,
// not eight: on the ten reference scenes the same to 0.00001 of SSIM (teapot-back 0.95002 against
// 0.95003), for 1.9 M instructions of the dragon's 800^2 camera frame instead of 3.4 M.
const vec2 LIT_FACE_RING[LIT_FACE_RING_TAPS] = vec2[](vec2(1.0, 0.0), vec2(0.0, 1.0), vec2(-1.0, 0.0), vec2(0.0, -1.0));

// One ring tap (its entry distance and coupling) against the face's entry distance: (coupling, 1)
// where it lies on the face's part, within two ring radii along the light, else (0, 0).
vec2 lit_face_ring_tap(float tap_entry, float tap_coupling, float face_entry, float ring) {
  return abs(tap_entry - face_entry) < 2.0 * ring ? vec2(tap_coupling, 1.0) : vec2(0.0);
}
// The face's coupling spread by the walk: its own (the inner half) and the ring's taps that count
// (ring_sum: lit_face_ring_tap summed), by the weights summed.
float lit_face_spread(float own, vec2 ring_sum) {
  return (LIT_FACE_OWN_WEIGHT * own + ring_sum.x) / (LIT_FACE_OWN_WEIGHT + ring_sum.y);
}
#endif
