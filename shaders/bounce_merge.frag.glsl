#version 450 core
// The bounce pass's third draw (`marble` only): the further bounces (bounce_further.frag.glsl, on a
// grid twice as coarse each way) brought to each texel of the first bounce's grid and added to it,
// with the emitters' albedo and Fresnel factors applied here, once per texel of this grid rather
// than once per lighting texel: the lighting pass then upsamples one texture (bounce_upsample.glsl).
// The further bounces are smooth over a texel of their grid: they are the first bounce (itself
// smooth over tens of pixels) gathered again over a disk of up to half the frame.
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"
#include "fresnel_f0.glsl"
#include "bounce_merge.glsl"

layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_bilateral.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;           // the first draw's, evened out
layout(binding = UNIT_LIGHTING_BOUNCE_FURTHER) uniform sampler2D u_further;  // the second draw's, evened out
uniform int u_scale;            // full-resolution pixels per texel of this draw and the first's
uniform int u_further_scale;    // and of the further bounces' (twice as many)
// rgb: irradiance / PI of all bounces per unit of the light's radiance, the emitters' albedo and
// Fresnel factors applied; a: the first bounce's mirrored part as it was (-1: the background).
layout(location = 0) out vec4 o_bounce;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 b = nearest_texel(u_bounce, t);  // GL_NEAREST, as the G-buffer (nearest_texel.glsl)
  if (b.a < 0.0) {
    o_bounce = b;
    return;
  }
  ivec2 px = t * u_scale;
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  vec2 uv = (vec2(px) + 0.5) / fullSize;
  vec3 P = surface_point(uv, textureLod(u_depth, uv, 0.0).r);
  vec3 N = decode_normal(textureLod(u_normal, uv, 0.0).xy);
  vec4 bF = bounce_bilateral(u_further, u_further_scale, P, N, px);
  o_bounce = bounce_merged(b, bF);
}
