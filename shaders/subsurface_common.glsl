// What the subsurface blur (subsurface_blur.frag.glsl) and the post pass, which upsamples its
// half-resolution result, share: depths and the millimetre scale on screen. Set by
// marble::setSubsurfaceUniforms (src/marble/render/subsurface_blur_pass.h). Needs gbuffer.glsl
// included before it.
layout(binding = UNIT_SURFACE_DEPTH) uniform sampler2D u_depth;  // the G-buffer's, full resolution
uniform vec2 u_near_far;
uniform float u_mm_per_unit;
uniform float u_pixels_per_mm_at_unit_depth;  // full-res pixels per mm at view distance 1 unit
uniform float u_reach_mm;                     // how far the blur reaches
uniform int u_scale;                          // 2: the blur runs at half resolution; 1: full
#include "nearest_texel.glsl"

float view_depth(float z) { return linear_depth(z, u_near_far); }  // scene units along the view axis

// How far apart in view depth two blur texels may lie and be taken for one surface, in mm at view
// depth `depth`: the blur's own reach, plus a few pixels' footprint for slanted surfaces.
float same_surface_tolerance_mm(float depth) { return u_reach_mm + 4.0 * depth / u_pixels_per_mm_at_unit_depth; }

// The blurred light at full-resolution pixel `px` (depth-buffer value z there): the up to
// four blur texels around it, weighted bilinearly (at full resolution: the one texel),
// keeping only those on stone at about the same depth (a joint bilateral upsample, Kopf et
// al. 2007; each texel's alpha holds its view depth, 0 on the background). Where none
// qualifies (slivers thinner than a texel), the one on stone nearest in depth -- light from a
// neighbouring surface rather than none; zero if all four are background.
vec3 upsample_blurred(sampler2D blurred, ivec2 px, float z) {
  vec2 t = vec2(px) / float(u_scale);  // texel h sits at pixel h * scale (blur_texel.glsl)
  ivec2 i0 = ivec2(floor(t));
  vec2 f = t - vec2(i0);
  ivec2 last = textureSize(blurred, 0) - 1;
  float depth = view_depth(z);
  float tolerance_mm = same_surface_tolerance_mm(depth);
  vec3 sum = vec3(0.0), nearest = vec3(0.0);
  float weight = 0.0, nearestGap = 1e30;
  for (int k = 0; k < 4; ++k) {
    ivec2 c = ivec2(k & 1, k >> 1);
    ivec2 h = min(i0 + c, last);
    float w = (c.x == 1 ? f.x : 1.0 - f.x) * (c.y == 1 ? f.y : 1.0 - f.y);
    vec4 b = nearest_texel(blurred, h);  // the blur's result is GL_NEAREST (SubsurfaceBlurPass)
    float gap = b.a > 0.0 ? abs(b.a - depth) : 1e30;
    if (gap < nearestGap) {
      nearestGap = gap;
      nearest = b.rgb;
    }
    if (gap * u_mm_per_unit > tolerance_mm) w = 0.0;
    sum += w * b.rgb;
    weight += w;
  }
  return weight > 1e-4 ? sum / weight : nearest;
}
