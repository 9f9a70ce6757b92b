// The lighting pass's bounce (`marble`): the bounce pass's coarse samples (bounce_gather.frag.glsl,
// one per 4 x 4 lighting texels) brought to a lighting texel, weighted as a bilateral upsample:
// bilinear in the coarse grid, times how well each sample's surface continues the texel's own
// (both read from the G-buffer):
//   - its normal: max(N.Ns, 0)^8 (1 for equal normals, 0.5 at 24 degrees, 0.1 at 45);
//   - its distance from the texel's tangent plane against its distance from the texel: on one
//     smooth surface a neighbour a few pixels away lies within a few degrees of the plane; across
//     a depth step it mostly does not. Weight 1 - angle / 0.3 rad, clamped, the angle taken as
//     |N.(Ps - P)| / |Ps - P|;
//   - its distance against how far one surface can reach over the pixels between them (a pixel's
//     width at P over the cosine to the view, at most 1/0.2): 1 up to that, 0 from twice that. At
//     grazing normals (a tube's edge in front of another part) the plane test alone lets the part
//     behind through.
// Where the weights sum to less than BOUNCE_MIN_WEIGHT (no coarse sample around lies on this
// surface: a part thinner than the coarse grid) the best-matching of the four is taken whatever
// its bilinear weight, and where none matches at all, the mean of the four (a neighbour's bounce,
// rather than none). Such a part, in front of another, takes a wrong bounce: the marble golden's
// knot (a 12-pixel tube at 160²) is darker by up to 123 levels in a few pixels along the edges
// where one tube crosses another (docs/quality.md). Gathering in place there instead
// (bounce_gather) cost the dragon's light frames ~8-10 ms on llvmpipe even where it ran for a few
// pixels (its shader evaluates a branch under a lane mask): not kept.
// Error (docs/quality.md, "One bounce gathered coarsely"): against the gather at every lighting
// texel, relative RMSE 0.05 and SSIM 0.98 on the dragon lit from the side at 800² (SSIM within
// 0.003 of it against Cycles in the ten reference scenes): the bounce's finest emitters (1/32 of
// the light map's width, ~15 pixels on an object filling 500) are a little finer than the coarse
// grid, so it comes out a little smoother.
// Needs from the includer: u_depth, u_normal (the G-buffer's), gbuffer.glsl, deferred_common.glsl,
// marble_shading.glsl (f0_from_ior).

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;
// The further bounces' integrals and view factor (bounce_further.frag.glsl), on the same grid.
layout(binding = UNIT_LIGHTING_BOUNCE_FURTHER) uniform sampler2D u_bounce_further;
uniform int u_bounce_scale;     // full-resolution pixels per texel of the bounce pass
uniform vec3 u_pat_base_color;  // the stone's albedo between veins: the emitters' albedo
uniform float u_ior;            // the emitters' Fresnel F0 (their glossy reflection)

const float BOUNCE_MIN_WEIGHT = 0.05;

// Irradiance / PI that one bounce brings to the surface at full-resolution pixel px (point P,
// normal N), before P's own albedo and entry; with it, over P's albedo, the bounce's light that P's
// specular layer mirrors toward the camera (bounce.glsl, since session 10).
vec3 marble_bounce(vec3 P, vec3 N, ivec2 px) {
  vec2 t = vec2(px) / float(u_bounce_scale);  // coarse texel i stands for pixel i * scale
  ivec2 i0 = ivec2(floor(t));
  vec2 f = t - vec2(i0);
  ivec2 last = textureSize(u_bounce, 0) - 1;
  ivec2 fullSize = textureSize(u_depth, 0);
  // How far apart two points of one surface can be, per pixel between them: a pixel's width at P
  // over the surface's cosine to the view (no less than 0.2: 78 degrees).
  vec2 uv = (vec2(px) + 0.5) / vec2(fullSize);
  float pixel = length(surface_point(uv + vec2(1.0 / float(fullSize.x), 0.0), texelFetch(u_depth, px, 0).r) - P);
  float reach = pixel / max(abs(dot(N, normalize(u_camera_pos - P))), 0.2);
  vec4 sum = vec4(0.0), best = vec4(0.0), any = vec4(0.0);
  vec4 sumF = vec4(0.0), bestF = vec4(0.0), anyF = vec4(0.0);  // the further bounces', weighed alike
  float weight = 0.0, bestMatch = 0.0, anyCount = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 c = ivec2(k & 1, k >> 1);
    ivec2 ic = min(i0 + c, last);
    vec4 b = texelFetch(u_bounce, ic, 0);
    if (b.a < 0.0) continue;  // the background
    vec4 bF = texelFetch(u_bounce_further, ic, 0);
    any += b;
    anyF += bF;
    anyCount += 1.0;
    ivec2 ps = ic * u_bounce_scale;
    vec3 Ps = surface_point((vec2(ps) + 0.5) / vec2(fullSize), texelFetch(u_depth, ps, 0).r);
    vec3 Ns = decode_normal(texelFetch(u_normal, ps, 0).xy);
    float cn = max(dot(N, Ns), 0.0);
    cn *= cn;
    cn *= cn;
    vec3 d = Ps - P;
    float dist = length(d);
    float plane = dist > 0.0 ? clamp(1.0 - abs(dot(N, d)) / (0.3 * dist), 0.0, 1.0) : 1.0;
    // Not a surface behind or in front (at grazing normals the plane test alone lets those pass).
    float near = clamp(2.0 - dist / (reach * (length(vec2(ps - px)) + 1.0)), 0.0, 1.0);
    float match = cn * cn * plane * near;
    float wb = (c.x == 1 ? f.x : 1.0 - f.x) * (c.y == 1 ? f.y : 1.0 - f.y);
    sum += wb * match * b;
    sumF += wb * match * bF;
    weight += wb * match;
    if (match > bestMatch) {
      bestMatch = match;
      best = b;
      bestF = bF;
    }
  }
  vec4 b = weight >= BOUNCE_MIN_WEIGHT ? sum / weight : (bestMatch > 0.0 ? best : any / max(anyCount, 1.0));
  vec4 bF = weight >= BOUNCE_MIN_WEIGHT ? sumF / weight : (bestMatch > 0.0 ? bestF : anyF / max(anyCount, 1.0));
  // The gather's scalars (bounce.glsl): diffuse x albedo, glossy x Schlick's F split by F0.
  float F0 = f0_from_ior(u_ior).x;
  // The mirrored part: radiance emitters' albedo x b.a x F at the view's cosine. It is reflected
  // light, but returned with the light entering the stone, which the post pass multiplies by the
  // albedo at P, so divided by it: taken as the emitters' (the base colour), the two cancel. Exact
  // for a flat stone; on a veined one the mirror image is tinted by the vein under it (off by the
  // vein's contrast to the base colour), and it is spread by the subsurface blur's millimetres.
  float m = 1.0 - clamp(dot(N, normalize(u_camera_pos - P)), 0.0, 1.0), m2 = m * m;
  float Fv = F0 + (1.0 - F0) * m2 * m2 * m;
  // The further bounces (bounce_further.frag.glsl): the second, albedo x (the first's terms over
  // the emitters the camera sees), and the rest by the series 1 / (1 - albedo F), F the view factor
  // of that stone (at most 0.8: a point can see no more than its hemisphere, and the floor keeps
  // the series finite where the coarse sums overshoot).
  vec3 second = u_pat_base_color * (u_pat_base_color * bF.x + F0 * bF.y + (1.0 - F0) * bF.z);
  vec3 further = second / (1.0 - u_pat_base_color * (41.0 / 42.0) * min(bF.a, 0.8));
  return u_light_radiance * (u_pat_base_color * b.x + F0 * b.y + (1.0 - F0) * b.z + further + Fv * b.a);
}
