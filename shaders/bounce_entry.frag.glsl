#version 450 core
// The bounce pass's entry draw (`marble` only): the first bounce (bounce.glsl) gathered at the
// light's side of the stone, one texel per texel of a level of the reflective shadow map, so
// that the transmission carries it through (lighting.frag.glsl, marble_entering). Light that one
// lit part sends to another lit part enters the stone there with the light's own; where the second
// part is thin (a handle, a spout, a rim seen edge-on) it crosses to the side the camera sees. The
// camera-side gather (bounce_gather) cannot hold it: their receivers are surfaces
// the camera sees, and this light arrives on surfaces facing away from it. In Cycles' teapot lit
// from behind it is 16 % of the indirect light (the translucent teapot's less the opaque one's;
// docs/quality.md, "Fifteenth session: teapot-back's indirect light is the parts' lit rims lighting
// each other"); the rest crosses the air between the parts' lit rims, which the camera-side gather
// is meant to hold.
// Texel t of this grid is texel t of the map's level u_level (BouncePass: kEntryLevel): its
// surface (the light-weighted mean position and normal over it) is the receiver, so the grid
// depends on the mesh, the light and the material only, and the renderer re-gathers it when the
// light's map is redrawn or the base colour or ior change, not when the camera moves.
// Interleaved as the camera-side gather: each 2 x 2 block turns the pattern by quarters of its
// angular step, and the lighting pass reads the grid bilinearly.
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "deferred_common.glsl"
#include "rotation.glsl"
#include "bounce.glsl"
#include "bounce_radial_stratum.glsl"
#include "fresnel_f0.glsl"

uniform vec3 u_pat_base_color;  // the stone's albedo between veins: the emitters' albedo
uniform float u_ior;            // the emitters' Fresnel F0 (their glossy reflection)
uniform int u_level;            // the reflective shadow map's level this grid's texels are (BouncePass)

// rgb: irradiance / PI per unit of the light's radiance, the emitters' albedo and Fresnel factors
// applied (as bounce_merge.frag.glsl applies them to the camera-side gather); a: unused.
layout(location = 0) out vec4 o_entry;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 pw = texelFetch(u_bounce_position, t, u_level);
  vec3 n = texelFetch(u_bounce_normal, t, u_level).xyz;
  if (pw.w <= 0.0 || dot(n, n) < 1e-8) {
    o_entry = vec4(0.0);
    return;
  }
  vec3 P = pw.xyz / pw.w;
  vec3 N = normalize(n);
  ivec2 q = t & 1;
  // V = N: the mirrored part (w) is the camera's, not wanted here.
  vec4 b = bounce_gather(P, N, N, 0.25 * float(q.x + 2 * q.y), BOUNCE_RADIAL_MIDDLE);  // not evened out (bounce_radial_stratum.glsl)
  float F0 = f0_from_ior(u_ior).x;
  o_entry = vec4(u_pat_base_color * b.x + F0 * b.y + (1.0 - F0) * b.z, 1.0);
}
