// The bounce's bilateral upsamples (bounce_upsample.glsl: the bounce pass's grid to a lighting
// texel; bounce_merge.frag.glsl: the further bounces' grid, twice as coarse, to the bounce pass's):
// bilinear in the coarse grid (its texel i stands for full-resolution pixel i * scale), times how
// well each coarse sample's surface, read from the G-buffer at its pixel ps, continues the surface
// at pixel px (point P, normal N), the product of
//   - its normal: max(N.Ns, 0)^8 (1 for equal normals, 0.5 at 24 degrees, 0.1 at 45);
//   - its distance from P's tangent plane against its distance from P: on one smooth surface a
//     neighbour a few pixels away lies within a few degrees of the plane; across a depth step it
//     mostly does not. Weight 1 - angle / 0.3 rad, clamped, the angle taken as |N.(Ps - P)| / |Ps - P|;
//   - its distance against how far one surface can reach over the pixels between them (`reach`: a
//     pixel's width at P over the cosine to the view, at most 1/0.2): 1 up to that, 0 from twice
//     that. At grazing normals (a tube's edge in front of another part) the plane test alone lets
//     the part behind through.
// Where the weights sum to less than BOUNCE_MIN_WEIGHT (no coarse sample around lies on this
// surface: a part thinner than the coarse grid) the best-matching of the four is taken whatever
// its bilinear weight, and where none matches at all, the mean of the four (a neighbour's bounce,
// rather than none). Coarse texels with alpha < 0 are the background: left out.
// Needs from the includer: u_depth, u_normal (the G-buffer's), gbuffer.glsl, deferred_common.glsl.

#include "nearest_texel.glsl"

const float BOUNCE_MIN_WEIGHT = 0.05;

// How far apart two points of one surface can be, per pixel between them, at pixel px.
float bounce_reach(vec3 P, vec3 N, ivec2 px, vec2 fullSize) {
  vec2 uv = (vec2(px) + 0.5) / fullSize;
  float pixel = length(surface_point(uv + vec2(1.0 / fullSize.x, 0.0), textureLod(u_depth, uv, 0.0).r) - P);
  return pixel / max(abs(dot(N, normalize(u_camera_pos - P))), 0.2);
}

// The match of a coarse sample at pixel ps (point Ps, normal Ns) to the surface at px.
float bounce_match_point(vec3 P, vec3 N, float reach, ivec2 px, ivec2 ps, vec3 Ps, vec3 Ns) {
  float cn = max(dot(N, Ns), 0.0);
  cn *= cn;
  cn *= cn;
  vec3 d = Ps - P;
  float dist = length(d);
  float plane = dist > 0.0 ? clamp(1.0 - abs(dot(N, d)) / (0.3 * dist), 0.0, 1.0) : 1.0;
  float near = clamp(2.0 - dist / (reach * (length(vec2(ps - px)) + 1.0)), 0.0, 1.0);
  return cn * cn * plane * near;
}

// The surface point and normal at pixel ps, as the matches read them (through the samplers: the
// G-buffer is GL_NEAREST, nearest_texel.glsl; ps lies in the frame).
vec3 bounce_point(ivec2 ps, vec2 fullSize) {
  vec2 uv = (vec2(ps) + 0.5) / fullSize;
  return surface_point(uv, textureLod(u_depth, uv, 0.0).r);
}
vec3 bounce_normal(ivec2 ps) { return decode_normal(nearest_texel(u_normal, ps).xy); }

float bounce_match(vec3 P, vec3 N, float reach, ivec2 px, ivec2 ps, vec2 fullSize) {
  return bounce_match_point(P, N, reach, px, ps, bounce_point(ps, fullSize), bounce_normal(ps));
}

// A grid of bounce samples as the upsample reads it: texel i (0..last) stands for full-resolution
// pixel i * scale and is stored at origin + i of the texture, except, where `evenFromCoarse`, the
// texels with both indices even: they are the pixels of the grid twice as coarse at the texture's
// origin, texel i / 2 (the bounce pass's refined grid, BouncePass: its other texels are gathered
// only where the coarse grid fails, the rest left out, alpha -1).
struct BounceGrid {
  int scale;
  ivec2 last;
  ivec2 origin;
  bool evenFromCoarse;
};

ivec2 bounce_grid_texel(BounceGrid g, ivec2 i) {
  return g.evenFromCoarse && ((i.x | i.y) & 1) == 0 ? i / 2 : g.origin + i;
}

// The grid's value at pixel px, weighed as above (zero where all four are background).
vec4 bounce_bilateral_in(sampler2D grid, BounceGrid g, vec3 P, vec3 N, ivec2 px) {
  vec2 t = vec2(px) / float(g.scale);
  ivec2 i0 = ivec2(floor(t));
  vec2 f = t - vec2(i0);
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  float reach = bounce_reach(P, N, px, fullSize);
  vec4 sum = vec4(0.0), best = vec4(0.0), any = vec4(0.0);
  float weight = 0.0, bestMatch = 0.0, anyCount = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 c = ivec2(k & 1, k >> 1);
    ivec2 ic = min(i0 + c, g.last);
    vec4 b = nearest_texel(grid, bounce_grid_texel(g, ic));  // the grids are GL_NEAREST
    if (b.a < 0.0) continue;  // the background
    any += b;
    anyCount += 1.0;
    float match = bounce_match(P, N, reach, px, ic * g.scale, fullSize);
    float wb = (c.x == 1 ? f.x : 1.0 - f.x) * (c.y == 1 ? f.y : 1.0 - f.y);
    sum += wb * match * b;
    weight += wb * match;
    if (match > bestMatch) {
      bestMatch = match;
      best = b;
    }
  }
  return weight >= BOUNCE_MIN_WEIGHT ? sum / weight : (bestMatch > 0.0 ? best : any / max(anyCount, 1.0));
}

// A whole texture as the grid.
vec4 bounce_bilateral(sampler2D grid, int scale, vec3 P, vec3 N, ivec2 px) {
  return bounce_bilateral_in(grid, BounceGrid(scale, textureSize(grid, 0) - 1, ivec2(0), false), P, N, px);
}

