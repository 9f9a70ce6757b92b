#version 450 core
// The bounce pass (`marble` only): the one diffuse bounce (bounce.glsl) gathered at a sixteenth
// of the lighting pass's texels (a quarter of its resolution each way; an eighth of the frame's at
// the blur's default half). Texel i stands for full-resolution pixel i * u_scale, as the lighting
// pass's texel h stands for pixel h * its scale, so that the upsample (bounce_upsample.glsl) can
// read the surface point and normal each sample was gathered for from the G-buffer itself.
// The bounce is smooth over many pixels (its emitters are a disk of half the light map's width
// around the point, finest near it at 1/32 of it: tens of pixels on an object that fills the
// frame), so coarser samples lose little where they lie on the receiver's surface.
#include "gbuffer.glsl"
#include "paper_shading.glsl"
#include "deferred_common.glsl"
#include "rotation.glsl"
layout(binding = UNIT_LIGHTING_DEPTH) uniform sampler2D u_depth;
// The bounce's occlusion near the receiver against this depth (camera-side gathers only).
#define BOUNCE_SCREEN_OCCLUSION
#include "bounce_screen_occlusion.glsl"
#include "bounce.glsl"
#include "bounce_radial_stratum.glsl"

layout(binding = UNIT_LIGHTING_NORMAL) uniform sampler2D u_normal;
uniform int u_scale;  // full-resolution pixels per texel of this pass
// rgb: the gathered bounce per unit of the light's radiance (irradiance / PI: diffuse before the
// emitters' albedo, glossy in two parts before the Fresnel factor; bounce.glsl); a: the radiance
// the surface's specular layer mirrors of it (before the emitters' albedo and the Fresnel factor;
// >= 0) where a surface was gathered for, -1 on the background (BouncePass clears to it).
layout(location = 0) out vec4 o_bounce;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy) * u_scale;
  ivec2 size = textureSize(u_depth, 0);
  if (any(greaterThanEqual(px, size))) {
    o_bounce = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  vec2 uv = (vec2(px) + 0.5) / vec2(size);  // px's centre: its depth and normal through the samplers (GL_NEAREST: nearest_texel.glsl)
  float depth = textureLod(u_depth, uv, 0.0).r;
  if (depth >= 1.0) {
    o_bounce = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  vec3 P = surface_point(uv, depth);
  vec3 N = decode_normal(textureLod(u_normal, uv, 0.0).xy);
  // Interleaved sampling (bounce.glsl): each texel of a 2 x 2 block turns the pattern by another
  // quarter of its angular step; the four turns together sample the rings 4x as densely in angle.
  // The fixed pattern alone swung SSIM against Cycles by up to 0.03 with its turn (bunny-side
  // 0.892-0.921 over four turns; docs/quality.md, "Eleventh session"), the interleaved one is at or
  // above the four turns' mean in every scene. The next step evens the four turns out over each
  // block (bounce_deinterleave.frag.glsl) before the further bounces and the merge read them; the
  // block's four texels also read the inner rings at four radii (bounce_radial_stratum.glsl).
  ivec2 q = ivec2(gl_FragCoord.xy) & 1;
  o_bounce = bounce_gather(P, N, normalize(u_camera_pos - P), 0.25 * float(q.x + 2 * q.y),
                           bounce_radial_stratum(ivec2(gl_FragCoord.xy)));
}
