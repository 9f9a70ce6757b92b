// Physically based marble (render mode `marble`): microfacet specular, diffuse with an
// energy split, light transmitted through thin parts with measured extinction, PCF shadows
// from the light's distance map, and a procedural studio environment. Linear HDR out.
// Needs from the includer: PI, u_light_shadow (the light's depth, compare mode) and light_vector
// (deferred_common.glsl).

// GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007, eq. 33). a = roughness^2.
float ggx_distribution(float NoH, float a) {
  float a2 = a * a;
  float d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (PI * d * d);
}

// Height-correlated Smith visibility V = G / (4 NoL NoV) (Heitz 2014, eq. 99; Filament 4.4.2).
float smith_ggx_visibility(float NoV, float NoL, float a) {
  float a2 = a * a;
  float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
  float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
  return 0.5 / max(gv + gl, 1e-6);
}

// Fresnel reflectance of a dielectric of relative index eta for unpolarized light arriving at
// cosine c (c = H.V for a microfacet): the exact formula (Walter et al. 2007, eq. 22), as Cycles'
// fresnel_dielectric_cos, which its Principled BSDF uses for the specular layer (its
// interpolate_fresnel_color with Specular = F0 / 0.08 and no tint reduces to exactly this).
// Schlick's (1994) F0 + (1 - F0)(1 - c)^5, used before session 10, is 13 % low at c = 0.75 and
// 22 % low at c = 0.5 for eta = 1.5: the side-lit scenes' highlights (c = 0.6-0.8) came out
// 0.66-0.88 of Cycles' (docs/quality.md, "Tenth session"). eta = 1 gives 0, c = 0 gives 1.
float fresnel_dielectric(float c, float eta) {
  c = clamp(c, 0.0, 1.0);
  float g = sqrt(max(eta * eta - 1.0 + c * c, 0.0));  // eta >= 1 (ior's range): no total reflection
  float a = (g - c) / max(g + c, 1e-6);
  float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

// The highlight integrated over a pixel's footprint. A pixel (of the 800^2 frame that
// --supersample 4 averages, or of Cycles' --box film) is the mean of the lobe over the normals its
// area covers, not the lobe at its centre: the stone's lobe (roughness 0.15, alpha 0.0225, about
// 1.3 degrees) is narrower than the 2-4 degrees a pixel's normals turn across the back-lit
// silhouettes, so its peak often falls between pixel centres. Across a pixel the normal is taken
// as linear on each side of its centre, reaching the midpoints to its four neighbours
// (footprint_mean_distribution); near its peak GGX is, in the tangent plane of N0, alpha^2 / (pi (alpha^2 + |s - h|^2)^2) with s
// the normal's and h the half vector's tangential part (exact to a relative alpha^2 ~ 5e-4 at any
// angle, with |s - h| the sine: GGX's cos^4 (alpha^2 + tan^2)^2 is (alpha^2 cos^2 + sin^2)^2).
// The pixel's mean is then this density's mass in the parallelogram the footprint's normals
// cover, over the parallelogram's area: the mass of a radial density whose radial CDF is
// r^2 / (alpha^2 + r^2) in a convex polygon is a sum over its edges (a fan of triangles from
// the lobe's centre, integrated in angle), each edge at signed distance p from the centre, from
// l0 to l1 along it, giving (p / k) (atan(l1 / k) - atan(l0 / k)) / (2 pi), k = sqrt(alpha^2 + p^2):
// a closed form, no samples. It replaces the lobe widened by the footprint's variance (Kaplanyan
// et al. 2016; Tokuyoshi & Kaplanyan 2019, used before session 19), which spread a glint
// symmetrically about each pixel centre: on teapot-back the lid rim's glint, whose peak lies on the
// boundary between two rows of the 800^2 frame, was split 1.7 : 1 between two 200^2 pixels where
// Cycles splits it 3.9 : 1 (docs/quality.md, "Nineteenth session"). The exact integral also
// keeps GGX's tail the stone's own (the mean of alpha^2 / (pi r^4) over a pixel far from the peak
// is the value at its centre), which the widening needed a Beckmann mix for (session 14).
// A jump to another surface is capped as before: the footprint's normals spread at most as far as
// 2 sigma^2 (their variance over the pixel) = SPECULAR_FOOTPRINT_MAX_A2 (Tokuyoshi & Kaplanyan's
// kappa, 0.18).
const float SPECULAR_FOOTPRINT_MAX_A2 = 0.18;

// The normal's change per pixel on the two sides of a pixel along one axis (each toward +axis;
// on: that neighbour is on the object). Each side keeps its own difference, so the footprint's
// normals reach the midpoints to both neighbours and the pixels' footprints tile the surface's
// normals without gaps or overlaps: with one difference for both sides (the smaller, session 16)
// a row whose neighbours turned 3.4 and 2.2 degrees away left a 0.6-degree band to neither, and
// a glint there lost its light (teapot-back's lid rim: docs/quality.md, "Nineteenth session"). A
// side off the object, or one that turns more than 3x as far as the other (a depth edge inside the
// object: a part in front, the far side of a fold, whose difference is no change of this
// surface's normal; taking it erased silhouette glints Cycles keeps: dragon-back's brightest pixel
// 0.28 of Cycles' converged value, "Sixteenth session"), is mirrored from the other side.
void footprint_axis_steps(inout vec3 before, bool before_on, inout vec3 after, bool after_on) {
  if (!before_on && !after_on) {
    before = after = vec3(0.0);
    return;
  }
  float b2 = dot(before, before), a2 = dot(after, after);
  if (!before_on || (after_on && b2 > 9.0 * a2)) before = after;
  else if (!after_on || a2 > 9.0 * b2) after = before;
}

// atan(l1 / k) - atan(l0 / k) (l1 > l0, k > 0), the angle an edge subtends, in one atan.
float edge_angle(float l0, float l1, float k) { return atan(k * (l1 - l0), k * k + l0 * l1); }

// An edge from P along the unit direction e for len (in a 2D frame of the tangent plane of N,
// relative to the lobe's centre): its share of the lobe's mass (z; positive where the centre
// lies to the left of the edge) and of the mass's first moment about the centre (xy), both
// times 2 pi. The moment of a radial density f(r) is the boundary integral of its radial
// antiderivative times the outward normal (s f(|s|) is the gradient of
// -alpha^2 / (2 pi (alpha^2 + r^2)) for GGX), which along an edge is the same angle over k as the
// mass's: -alpha^2 (angle / k) times the normal.
vec3 edge_mass(vec2 P, vec2 e, float len, float a2) {
  vec2 n = vec2(e.y, -e.x);  // the right-hand normal: outward for a counter-clockwise polygon
  float p = dot(P, n);       // signed distance of the centre from the edge's line
  float k = sqrt(a2 + p * p);
  float l0 = dot(P, e);
  float t = edge_angle(l0, l0 + len, k) / k;
  return vec3(-a2 * t * n, p * t);
}

// A side vector s given a height of at least w across the unit direction `across` (on its own
// side; on `side` where it has none), so that a parallelogram of it keeps an area.
vec2 with_height(vec2 s, vec2 across, float w, float side) {
  float height = dot(s, across);
  float sgn = height == 0.0 ? side : sign(height);
  return s + (sgn * max(abs(height), w) - height) * across;
}

// The GGX lobe of the stone (alpha a) averaged over a pixel's footprint (see the top of this
// part): N the pixel's normal, H the half vector, bx, ax, by, ay the normal's change to the
// neighbours before and after it along x and y (footprint_axis_steps; each toward +axis). The
// normal is taken as linear in each half of the pixel, reaching the midpoints to the neighbours.
// Returns the mean D, and in N_lobe the footprint's normal at the centroid of the
// lobe's mass within it: there the factors that vary more slowly are evaluated (N.L, N.V,
// Smith's shadowing), which is exact for factors linear across the lobe. They are not constant:
// at a back-lit glint N.V ~ 0.1 and 1 / (4 N.V) changes by 25 % across the stone's lobe; taken at
// the pixel's centre or at the footprint's normal nearest H, the lid rim's glint on teapot-back
// was 0.18 / 0.22 off the brute-force sub-pixel integral (relative L2 over its 18 x 6 pixels of
// the 800^2 frame; four quarters of the pixel), at the centroid 0.10 (docs/quality.md,
// "Nineteenth session"). Cost: each half's four edges are one atan each; a single parallelogram
// for the whole pixel put 1.2x the light on a row whose neighbours turned 3.4 and 2.2 degrees
// away, four quarters gave what two halves give at twice the edges.
float footprint_mean_distribution(vec3 N, vec3 H, vec3 bx, vec3 ax, vec3 by, vec3 ay, float a, out vec3 N_lobe) {
  bx -= N * dot(N, bx); ax -= N * dot(N, ax); by -= N * dot(N, by); ay -= N * dot(N, ay);  // tangential parts
  float spread = (dot(bx, bx) + dot(ax, ax) + dot(by, by) + dot(ay, ay)) / 12.0;
  if (spread > SPECULAR_FOOTPRINT_MAX_A2) {
    float shrink = sqrt(SPECULAR_FOOTPRINT_MAX_A2 / spread);
    bx *= shrink; ax *= shrink; by *= shrink; ay *= shrink;
  }
  // Far from the lobe (the half vector more than 4 footprint radii R away) the mean is GGX at the
  // centre with its second-order term, and costs no edges: the mean of a function over a
  // footprint whose normals' variance totals T is f + (T / 4) times its Laplacian, for GGX's
  // alpha^2 / (pi g^2), g = alpha^2 + r^2, a factor 1 + 2 T (2 r^2 - alpha^2) / g^2 (up to 1.08 at
  // r = 4 R; the next term, of order (R / r)^4, under 1 %). T: each axis spans (|before| + |after|)
  // / 2, variance ~ (|before|^2 + |after|^2) / 24. So is a half vector behind the surface, which
  // the tangent plane would fold onto the front (a silhouette sample whose normal faces away,
  // buddha-back's (120,44): 1266 where GGX gives 0).
  float NoH = dot(N, H);
  vec3 h = H - N * NoH;
  float r2 = dot(h, h);
  float radius2 = 0.25 * (max(dot(bx, bx), dot(ax, ax)) + max(dot(by, by), dot(ay, ay)));
  if (NoH <= 0.0 || r2 >= 16.0 * radius2) {
    N_lobe = N;
    float variance = (dot(bx, bx) + dot(ax, ax) + dot(by, by) + dot(ay, ay)) / 24.0;
    float g = a * a + r2;
    return ggx_distribution(max(NoH, 0.0), a) * (1.0 + 2.0 * variance * (2.0 * r2 - a * a) / (g * g));
  }
  float a2 = a * a, w = 0.125 * a;
  // The footprint as two parallelograms, split across the axis whose two sides differ more (the
  // halves toward the neighbours before and after); along the other axis one span, centred
  // between the midpoints to its two neighbours. Each side is given a width of at least w
  // (alpha / 8: a smaller footprint is a point sample, its mean within 1 % of GGX at the centre,
  // and the mass / area quotient stays well conditioned in 32-bit floats). In a 2D frame of the
  // tangent plane; the halves share their middle edge.
  vec3 dx = ax - bx, dy = ay - by;
  if (dot(dx, dx) > dot(dy, dy)) {
    vec3 t = bx; bx = by; by = t;
    t = ax; ax = ay; ay = t;
  }
  vec3 t1 = normalize(cross(N, abs(N.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 t2 = cross(N, t1);
  mat2x3 frame = mat2x3(t1, t2);
  vec2 span = (0.5 * (bx + ax)) * frame, up = (0.5 * ay) * frame, down = (-0.5 * by) * frame;
  vec2 c = (0.25 * (ax - bx) - 0.25 * (bx + ax) - h) * frame;
  float span_len = length(span);
  vec2 along = span_len >= w ? span / span_len : vec2(1.0, 0.0);
  span_len = max(span_len, w);
  span = along * span_len;
  vec2 across = vec2(-along.y, along.x);
  up = with_height(up, across, w, 1.0);
  down = with_height(down, across, w, -1.0);
  float up_len = length(up), down_len = length(down);
  vec2 e_up = up / up_len, e_down = down / down_len;
  // Signed areas: a half traversed clockwise has negative mass and area alike.
  float area_up = span_len * dot(up, across), area_down = span_len * dot(down, across);
  vec3 middle = edge_mass(c, along, span_len, a2);
  vec3 m_up = middle + edge_mass(c + span, e_up, up_len, a2) + edge_mass(c + span + up, -along, span_len, a2) +
              edge_mass(c + up, -e_up, up_len, a2);
  vec3 m_down = middle + edge_mass(c + span, e_down, down_len, a2) + edge_mass(c + span + down, -along, span_len, a2) +
                edge_mass(c + down, -e_down, down_len, a2);
  vec3 m2 = (m_up / area_up + m_down / area_down) / (4.0 * PI);
  vec4 m = vec4(frame * m2.xy, m2.z);
  float mass = max(m.w, 0.0);
  N_lobe = normalize(N + h + (mass > 0.0 ? m.xyz / mass : vec3(0.0)));
  return mass;
}

#include "fresnel_f0.glsl"

// Split-sum environment BRDF, analytic fit (Karis 2014, "Physically Based Shading on Mobile").
vec3 env_brdf_approx(vec3 F0, float roughness, float NoV) {
  const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
  const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
  vec4 r = roughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
  vec2 AB = vec2(-1.04, 1.04) * a004 + r.zw;
  return F0 * AB.x + AB.y;
}

// Where P is looked up in the light's depth map: texture coordinates and the depth to compare,
// or false outside the map (nothing there casts a shadow). The point is first pushed out along
// its normal, against self-shadow acne.
bool shadow_lookup(vec3 P, vec3 N, mat4 light_view_proj, float texel_world, out vec3 uvz) {
  vec4 clip = light_view_proj * vec4(P + N * (2.0 * texel_world), 1.0);
  vec3 ndc = clip.xyz / clip.w;
  uvz = ndc * 0.5 + 0.5;
  uvz.z -= 1e-4;
  return all(lessThanEqual(abs(ndc.xy), vec2(1.0)));
}

// The light entering the stone is shadowed by receiver_plane_visibility (shadow_receiver_plane.glsl,
// the lighting pass): before session 25 by the lookup below (session 12: along N the lookup also
// moved sideways in the light's view, and a cast shadow's edge with it, 2 sin(theta) / cos(theta)
// texels along a surface the light grazes; on bunny-side marble lit 175 grazing-lit pixels that
// Cycles' occluders shadow; docs/quality.md, "Twelfth session: the front- and side-lit scenes").
//
// The highlight and the retro-reflection (bilinear_visibility, one comparison in the post pass) are
// shadowed from a point moved toward the light, not along N: there the lookup stays at the same
// place in the map and only its depth changes, by the depth a plane at that slant gains over the
// filter's reach, 2 texels x tan(theta) (cos floored at 0.05: 20 texels), and half a texel along N
// for the surface's curvature within a texel (Williams 1978's bias in its slope-scaled form, as
// OpenGL's polygon offset). Since session 25: a back light's glints lie where N.L is 0.2-0.3, and
// the lookup along N, 2 texels sideways in the light's view, saw past the edges of the shadows
// other parts cast there. Against Cycles' specular layer alone (the stone black, direct light, 1024
// samples; marble at 16 x 16 samples a pixel) the back-lit highlight's relative RMSE went 0.270 ->
// 0.135 (dragon) and 0.358 -> 0.204 (buddha), its energy 1.23 -> 1.12 and 1.43 -> 1.18 of Cycles'
// (docs/quality.md, "Twenty-fifth session: the highlight's shadow"). (Session 12 tried this and
// measured the opposite, dragon-back SSIM 0.743 -> 0.734, k 1.10 -> 1.77, against the references
// and the highlight of then: glints point-sampled at the pixel's centre normal, before session 19
// integrated the lobe over each pixel's normals, and references whose glints had not converged,
// before session 16.)
bool shadow_lookup_along_light(vec3 P, vec3 N, mat4 light_view_proj, float texel_world, out vec3 uvz) {
  vec3 L = light_vector(P);
  float c = clamp(abs(dot(N, L)), 0.05, 1.0);
  vec4 clip = light_view_proj * vec4(P + L * (2.0 * texel_world * sqrt(1.0 - c * c) / c) + N * (0.5 * texel_world), 1.0);
  vec3 ndc = clip.xyz / clip.w;
  uvz = ndc * 0.5 + 0.5;
  uvz.z -= 1e-4;
  return all(lessThanEqual(abs(ndc.xy), vec2(1.0)));
}

// One bilinear 2x2 comparison: a quarter of a 4-tap filter's cost, with an edge one texel
// narrower. The post pass shadows the reflected light with it -- the highlight, already
// shaped by the GGX lobe -- where the four taps were a third of the pass's time on llvmpipe.
// Looked up along the light (shadow_lookup_along_light, above).
float bilinear_visibility(vec3 P, vec3 N, mat4 light_view_proj, float texel_world) {
  vec3 uvz;
  if (!shadow_lookup_along_light(P, N, light_view_proj, texel_world, uvz)) return 1.0;
  return texture(u_light_shadow, uvz);
}

// --- procedural studio environment (no file needed) ---
// A dark floor, grey walls, a bright ceiling, a large softbox above-front and two strip
// lights behind-left and behind-right, so polished stone shows highlights from every side.
struct Softbox { vec3 axis; float radius; float radiance; };
const int SOFTBOXES = 3;
Softbox softbox(int i) {
  if (i == 0) return Softbox(normalize(vec3(0.0, 0.85, 0.55)), 0.45, 3.0);
  if (i == 1) return Softbox(normalize(vec3(-0.9, 0.25, -0.45)), 0.18, 4.0);
  return Softbox(normalize(vec3(0.9, 0.25, -0.45)), 0.18, 4.0);
}
vec3 studio_background(vec3 d) {
  return mix(vec3(0.02), vec3(0.12, 0.12, 0.13), smoothstep(-0.4, 0.7, d.y));
}
// Radiance seen along d, blurred over `blur` radians (a stand-in for prefiltering by
// roughness); blur_cs = (cos(blur), sin(blur)), given by the caller, which has them once per
// frame. Widening a box keeps its power: radiance scales by (r / (r + blur))^2.
vec3 studio_radiance(vec3 d, float blur, vec2 blur_cs) {
  vec3 c = studio_background(d);
  for (int i = 0; i < SOFTBOXES; ++i) {
    Softbox b = softbox(i);
    float r = b.radius;
    float k = r / (r + blur);
    // Compared in cosine space (no acos per pixel): inside the box's cone, fading at its edge.
    // The cone's edges cos(r + 0.02 + blur) and cos(max(r - 0.02 - blur, 0)) by the angle-sum
    // identities, so the only trigonometry is the compile-time cos and sin of r +- 0.02
    // (llvmpipe evaluates cos() per pixel, uniform argument or not).
    float outer = cos(r + 0.02) * blur_cs.x - sin(r + 0.02) * blur_cs.y;
    float inner = blur >= r - 0.02 ? 1.0 : cos(r - 0.02) * blur_cs.x + sin(r - 0.02) * blur_cs.y;
    c += b.radiance * k * k * smoothstep(outer, inner, dot(d, b.axis));
  }
  return c;
}
// Irradiance / PI for a surface with normal n: the gradient's cosine-weighted average plus
// each softbox as a small source of solid angle pi r^2.
vec3 studio_diffuse(vec3 n) {
  vec3 e = mix(vec3(0.02), vec3(0.12, 0.12, 0.13), 0.5 + 0.45 * n.y);
  for (int i = 0; i < SOFTBOXES; ++i) {
    Softbox b = softbox(i);
    e += b.radiance * b.radius * b.radius * max(dot(n, b.axis), 0.0);
  }
  return e;
}
