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
// - gap: how far the ray's point on the hit pixel lies behind the visible face, along the camera's
//   ray. On the mirror line's pixels 0.03-0.06 scene units; where the ray meets the visible face
//   itself 0.00-0.01 (the bisection's leftover step).
// - below: how far that point lies beyond the light's entry surface, along the light's ray (the
//   light's map, light_entry_at). On the line -0.01 ... 0.05; beside it, where the ray runs inside
//   a part the light does not reach directly, 0.1-0.2.
// Thresholds measured on the ten reference scenes (main dc79294; the SSIM of teapot-back, 0.94666
// on main): gap > 0.01 / 0.02 / 0.03 / 0.04 with |below| < 0.02 gave 0.94888 / 0.94899 / 0.94881 /
// 0.94841; |below| < 0.01 / 0.015 / 0.02 / 0.025 / 0.05 / 0.1 with gap > 0.02 gave 0.94840 / 0.94863
// / 0.94899 / 0.94880 / 0.94749 / 0.94557 (a wider band takes faces the ray only passes near). Kept:
// gap > 0.03, |below| < 6 light-map texels (0.020 on the reference scenes), the ten scenes' mean
// the highest of five pairs measured. Valid for a scene scaled as the reference scenes (the object
// normalized to the unit sphere); the gap is in scene units, not tied to the pixel.
#ifndef MIRROR_LIT_FACE_GLSL
#define MIRROR_LIT_FACE_GLSL
const float MIRROR_LIT_FACE_GAP = 0.03;     // scene units behind the visible face
const float MIRROR_LIT_FACE_TEXELS = 6.0;   // light-map texels from the light's entry surface

// The parameter t of the ray clipP + t clipR (clip space) whose projection falls on ndc, solved on
// the screen axis along which the ray moves faster (the other may be still).
float mirror_ray_t_at(vec4 clipP, vec4 clipR, vec2 ndc) {
  vec2 num = ndc * clipP.w - clipP.xy, den = clipR.xy - ndc * clipR.w;
  return abs(den.x) > abs(den.y) ? num.x / den.x : num.y / den.y;
}

// Whether the ray's point on the hit pixel, gap behind the visible face and below beyond the light's
// entry surface (light_texel: the light map's texel in scene units), meets a lit face hidden there.
bool mirror_meets_lit_face(float gap, float below, float light_texel) {
  return gap > MIRROR_LIT_FACE_GAP && abs(below) < MIRROR_LIT_FACE_TEXELS * light_texel;
}
#endif
