#version 450 core
// The bounce pass's merge (`marble` only): the further bounces (the radiosity's 3D grid,
// further_radiosity.h) read at each texel's surface point and added to the first bounce there,
// with the emitters' albedo and Fresnel factors applied here, once per texel of this grid rather
// than once per lighting texel: the lighting pass then upsamples one texture (bounce_upsample.glsl).
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "gbuffer.glsl"
#include "deferred_common.glsl"
#include "fresnel_f0.glsl"
#include "nearest_texel.glsl"
#include "bounce_merge.glsl"

layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;

layout(binding = UNIT_LIGHTING_BOUNCE) uniform sampler2D u_bounce;           // the first draw's, evened out
uniform int u_scale;            // full-resolution pixels per texel of this draw and the first's
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
  o_bounce = bounce_merged(b, P);
}
