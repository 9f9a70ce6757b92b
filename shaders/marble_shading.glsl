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

// Geometric specular antialiasing (Kaplanyan et al. 2016; Tokuyoshi & Kaplanyan 2019, "Improved
// Geometric Specular Antialiasing"): a pixel's highlight is the GGX lobe averaged over the normals
// its footprint covers; their spread widens the lobe, alpha^2 += 2 sigma^2 (GGX's alpha^2 as twice
// the slopes' variance, Beckmann's relation). sigma^2: the normal's variance over a box one pixel
// wide, d_x^2 / 12 + d_y^2 / 12 (a box pixel: what --supersample's block average and Cycles' --box
// reference integrate), d the normal's change to the next pixel along each axis. Without it a
// highlight narrower than a pixel is point-sampled: on the side-lit reference scenes (a highlight's
// core ~ a pixel of the 800^2 frame) marble's highlights landed on different pixels than Cycles'
// (docs/quality.md, "Tenth session"). d^2 per axis: footprint_axis_d2. A jump to another surface
// is capped at SPECULAR_FOOTPRINT_MAX_A2 (Tokuyoshi & Kaplanyan's kappa, 0.18).
const float SPECULAR_FOOTPRINT_MAX_A2 = 0.18;
float specular_footprint_a2(float dx2, float dy2) {
  return min(2.0 * (dx2 + dy2) / 12.0, SPECULAR_FOOTPRINT_MAX_A2);
}

// The normal's squared change per pixel along one axis, from the squared differences to the two
// neighbours on it (negative: that neighbour is off the object, left out): the smaller of the two
// (the minmod rule of slope limiters, van Leer 1979). On a smooth surface the two sides agree to
// the surface's change of curvature; where one neighbour lies on another surface (a depth edge
// inside the object: a part in front, the far side of a fold) its difference is no spread of this
// surface's normal, and taking it (the 2x2 quad's one difference, used before session 16) capped
// the lobe at kappa on the pixel next to the edge, which erased silhouette glints Cycles keeps
// (dragon-back's brightest pixel 0.28 of Cycles' converged value; docs/quality.md, "Sixteenth
// session"). Error: where the normal turns faster on one side (a crease) the spread is that of
// the flatter side; the crease's own pixels are then closer to point-sampled.
float footprint_axis_d2(float before, float after) {
  if (before < 0.0) return max(after, 0.0);
  if (after < 0.0) return before;
  return min(before, after);
}

// The stone's GGX lobe (alpha^2 = a_stone2) averaged over a pixel's normals, which widen it to
// a2 = a_stone2 + specular_footprint_a2 (at most 1). Adding the kernel's variance to alpha^2 is
// exact for Beckmann's Gaussian slopes, but GGX's slopes, density alpha^2 / (pi (alpha^2 + s^2)^2),
// have no finite variance: averaging over a narrow kernel leaves their tail alpha^2 / (pi s^4)
// as it was, while GGX at a2 scales it by a2 / a_stone2 -- up to 360x the stone's (0.0005 against
// the cap 0.18) at silhouettes, where the normal turns fast across a pixel; there, times the
// grazing 1 / (4 N.V), it lit whole rims far from any highlight (teapot-back's terminator band
// 3-9x Cycles' highlight; docs/quality.md, "Fourteenth session"). So: a normalised mix of GGX
// at a2 weighted w = a_stone2 / a2, whose tail w a2 / (pi s^4) is then the stone's exactly, and a
// Beckmann core at a2 carrying the rest. w = 1 (no spread): the stone's GGX (to rounding); w -> 0:
// Beckmann at a2, the Gaussian convolution. Measured against marble's own highlight rendered with
// 16x the samples and no widening, the highlight's relative RMSE falls in all ten reference scenes
// (tests/specular_gl_test.cpp, WidenedLobeAddsNoLightAwayFromTheHighlight: 0.86-0.89 of the
// integrated light away from the highlight, where GGX at a2 gave 7-8x).
float footprint_filtered_distribution(float NoH, float a_stone2, float a2) {
  float w = a_stone2 / a2;
  if (w >= 1.0) return ggx_distribution(NoH, sqrt(a2));
  float c2 = max(NoH * NoH, 1e-6);
  float beckmann = exp((c2 - 1.0) / (a2 * c2)) / (PI * a2 * c2 * c2);
  return w * ggx_distribution(NoH, sqrt(a2)) + (1.0 - w) * beckmann;
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

// The light entering the stone is shadowed from a point moved toward the light, not along N
// (shadow_lookup). Along N the lookup also moves sideways in the light's view, by 2 texels x
// sin(theta), and a cast shadow's edge with it: on a surface the light grazes (N.L = cos theta
// small) that is 2 sin(theta) / cos(theta) texels along the surface, ~20 at N.L 0.1: on bunny-side
// marble lit 175 grazing-lit pixels (N.L median 0.10) that Cycles' occluders shadow, 1-4 pixels into
// the shadow (docs/quality.md, "Twelfth session: the front- and side-lit scenes"). Moved along the
// light's own ray the lookup stays at the same place in the map and only its depth changes: by
// the depth a plane at that slant gains over the filter's reach (2 texels, the four taps' bilinear
// span) tan(theta) = sin / cos, cos floored at 0.05 (20 texels), and half a texel along N for the
// surface's curvature within a texel (a depth bias scaled by the slope: Williams 1978's bias, the
// slope-scaled form of OpenGL's polygon offset). The highlight keeps shadow_lookup
// (bilinear_visibility): with this lookup the back-lit dragon's grazing glints fell into the
// surface's own shadow (SSIM 0.743 -> 0.734, k 1.10 -> 1.77), which the diffuse light, weighted by
// N.L, does not show.
bool shadow_lookup_along_light(vec3 P, vec3 N, mat4 light_view_proj, float texel_world, out vec3 uvz) {
  vec3 L = light_vector(P);
  float c = clamp(abs(dot(N, L)), 0.05, 1.0);
  vec4 clip = light_view_proj * vec4(P + L * (2.0 * texel_world * sqrt(1.0 - c * c) / c) + N * (0.5 * texel_world), 1.0);
  vec3 ndc = clip.xyz / clip.w;
  uvz = ndc * 0.5 + 0.5;
  uvz.z -= 1e-4;
  return all(lessThanEqual(abs(ndc.xy), vec2(1.0)));
}

// Percentage-closer filtering (Reeves et al. 1987) with the hardware's depth comparison:
// each of the 4 taps is itself a bilinear 2x2 comparison, so 16 texels are weighed in all.
// The light entering the stone (marble_entering): looked up along the light (above).
float pcf_visibility(vec3 P, vec3 N, mat4 light_view_proj, float texel_world) {
  vec3 uvz;
  if (!shadow_lookup_along_light(P, N, light_view_proj, texel_world, uvz)) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(u_light_shadow, 0));
  float lit = texture(u_light_shadow, vec3(uvz.xy + vec2(-0.5, -0.5) * texel, uvz.z)) +
              texture(u_light_shadow, vec3(uvz.xy + vec2(0.5, -0.5) * texel, uvz.z)) +
              texture(u_light_shadow, vec3(uvz.xy + vec2(-0.5, 0.5) * texel, uvz.z)) +
              texture(u_light_shadow, vec3(uvz.xy + vec2(0.5, 0.5) * texel, uvz.z));
  return lit * 0.25;
}

// One bilinear 2x2 comparison: a quarter of pcf_visibility's cost, with an edge one texel
// narrower. The post pass shadows the reflected light with it -- the highlight, already
// shaped by the GGX lobe -- where the four taps were a third of the pass's time on llvmpipe.
float bilinear_visibility(vec3 P, vec3 N, mat4 light_view_proj, float texel_world) {
  vec3 uvz;
  if (!shadow_lookup(P, N, light_view_proj, texel_world, uvz)) return 1.0;
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
