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

layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
#include "bounce_bilateral.glsl"

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;           // the first draw's
layout(binding = UNIT_LIGHTING_BOUNCE_FURTHER) uniform sampler2D u_further;  // the second draw's
uniform int u_scale;            // full-resolution pixels per texel of this draw and the first's
uniform int u_further_scale;    // and of the further bounces' (twice as many)
uniform vec3 u_pat_base_color;  // the stone's albedo between veins: the emitters' albedo
uniform float u_ior;            // the emitters' Fresnel F0 (their glossy reflection)
// rgb: irradiance / PI of all bounces per unit of the light's radiance, the emitters' albedo and
// Fresnel factors applied; a: the first bounce's mirrored part as it was (-1: the background).
layout(location = 0) out vec4 o_bounce;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 b = texelFetch(u_bounce, t, 0);
  if (b.a < 0.0) {
    o_bounce = b;
    return;
  }
  ivec2 px = t * u_scale;
  vec2 fullSize = vec2(textureSize(u_depth, 0));
  vec3 P = surface_point((vec2(px) + 0.5) / fullSize, texelFetch(u_depth, px, 0).r);
  vec3 N = decode_normal(texelFetch(u_normal, px, 0).xy);
  vec4 bF = bounce_bilateral(u_further, u_further_scale, P, N, px);
  vec3 A = u_pat_base_color;
  // The first bounce's scalars (bounce.glsl): diffuse x albedo, glossy x Schlick's F split by F0.
  float F0 = f0_from_ior(u_ior).x;
  // The further bounces: the second, albedo x (the first's terms over the emitters the camera
  // sees), and the rest by the series 1 / (1 - albedo F), F the view factor of that stone (at most
  // 0.8: a point can see no more than its hemisphere, and the floor keeps the series finite where
  // the coarse sums overshoot).
  vec3 second = A * (A * bF.x + F0 * bF.y + (1.0 - F0) * bF.z);
  vec3 further = second / (1.0 - A * (41.0 / 42.0) * min(bF.a, 0.8));
  o_bounce = vec4(A * b.x + F0 * b.y + (1.0 - F0) * b.z + further, b.a);
}
