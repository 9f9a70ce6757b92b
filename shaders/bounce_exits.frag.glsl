#version 450 core
// The bounce's second kind of emitter (`marble` only; BouncePass's first draw, at the reflective
// shadow map's finest level): the far side of the first part the light meets. The light that
// entered a texel's surface (its flux E(d) x w, light_depth.frag.glsl) crosses the part, exit -
// entry thick along the light's ray (light_layers.frag.glsl), and the part of it the random walk
// carries through (slab_transport, the transmission's own: one place for the fact) leaves the far
// side as diffuse light. Back-lit, that glow of the thin parts (horns, spines, claws, a tail, a
// handle) is what lights the body beside them on the camera's side: in Cycles' dragon-back 85-89 %
// of the body's light in the shade is indirect (docs/quality.md, "Nineteenth session: the side-lit
// shade is the bounce"), and without these emitters only the light bounced through the stone stood
// in for it. Per texel: (exit point x phi, phi), phi = w x translucency x the transported fraction,
// so that the mipmaps (BouncePass) average the exit points weighted by what they emit, as the
// reflective shadow map's are weighted by w.
// Approximations, each stated:
// - the emitter's colour is the stone's base colour, as the reflected emitters' (bounce.glsl reads
//   one scalar per emitter and bounce_merge.frag.glsl multiplies by the albedo): phi keeps the
//   luminance of albedo x T / R_inf (Rec. 709 weights), not its redder hue through thick parts;
// - it leaves around the light's direction of travel (the exit's normal is not in the layers): exact
//   for a part crossed square to the light, and for a slanted one the same flux with its cosine lobe
//   turned by the part's slant;
// - the light's falloff is taken at the exit (bounce.glsl), not the entry: (1 + s / d)^2 off for a
//   part s thick at distance d from a point light (under 2 % for 20 mm at the scenes' 2 m; beyond
//   20 mm the walk carries under 1e-3 of it);
// - only the first part along each ray: light that crosses a second part behind it is not emitted.
const float PI = 3.14159265358979;  // before deferred_common.glsl, which needs it
#include "deferred_common.glsl"
#include "slab_transport.glsl"

// The reflective shadow map's position (x w, w) and the layers (entry, exit): bounce.glsl reads
// the same units; not included here because this draw writes the texture bounce.glsl reads as the
// exits' emitters.
layout(binding = UNIT_LIGHTING_BOUNCE_POSITION) uniform sampler2D u_bounce_position;
layout(binding = UNIT_LIGHTING_BOUNCE_LAYERS) uniform sampler2D u_bounce_layers;
uniform float u_mm_per_unit;
uniform float u_translucency;
uniform vec3 u_pat_base_color;  // the emitters' albedo (bounce_merge.frag.glsl applies it)
uniform float u_layer_texel;    // a texel of the layers at the object (scene units)

const float EXITS_MIN_TRANSPORT = 0.01;  // of the light the same surface reflects (T / R_inf)

layout(location = 0) out vec4 o_exit;    // exit point x phi, phi (scene units^2, as w)
layout(location = 1) out vec4 o_normal;  // the exit's normal x phi (its mean's direction: the emitters' normal)

// Where the light's ray through texel t leaves the first part it meets (its entry, the reflective
// shadow map's point, carried the layers' chord along the ray); w = 0 where there is none.
vec4 exit_at(ivec2 t) {
  vec4 pw = texelFetch(u_bounce_position, t, 0);
  vec2 layers = texelFetch(u_bounce_layers, t, 0).xy;
  float s = layers.y - layers.x;  // the first part's chord along the ray (scene units)
  // No surface, no exit behind the entry (LightDepthPass::kNoLayer, an open or inward-wound mesh).
  if (pw.w <= 0.0 || layers.y > 1e20 || s <= 0.0) return vec4(0.0);
  vec3 entry = pw.xyz / pw.w;
  return vec4(entry - light_vector(entry) * s, s);
}

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 e = exit_at(t);
  float w = texelFetch(u_bounce_position, t, 0).w;
  if (e.w <= 0.0) {
    o_exit = o_normal = vec4(0.0);
    return;
  }
  const vec3 luma = vec3(0.2126, 0.7152, 0.0722);
  float transported = dot(luma, u_pat_base_color * slab_transport(e.w * u_mm_per_unit)) / max(dot(luma, u_pat_base_color), 1e-6);
  // Only chords the layers resolve, over one of their texels: below it the entry and the exit are
  // point samples of a part no wider than the texel along the ray (the grazing chords at the light's
  // silhouettes, parts finer than the map), which the visibility test (bounce_crosses_stone, its
  // one-texel tolerance) does not count as stone either. Measured: chords under 3 mm emitting
  // cost buddha-side 0.008 of SSIM (docs/quality.md, "Twentieth session").
  // And only where the part lets through at least EXITS_MIN_TRANSPORT of what it reflects: the
  // thick parts' exits (most of a statue's body) emit less than that, and left at 0 their samples
  // cost the gathers one texture read instead of the cosines and the visibility test
  // (docs/performance.md, "Twentieth session").
  float phi = e.w > u_layer_texel && transported >= EXITS_MIN_TRANSPORT ? w * transported * u_translucency : 0.0;
  // The exit surface's normal from the exit points of the texel's neighbours (central differences,
  // one-sided where a neighbour's ray misses the part or leaves it elsewhere: an exit point over 4
  // texels away, a slope beyond 76 degrees), turned along the light's travel; the travel itself
  // where neither side of an axis has a neighbour.
  vec3 travel = -light_vector(e.xyz);
  ivec2 size = textureSize(u_bounce_layers, 0);
  vec3 axis[2];
  for (int k = 0; k < 2; ++k) {
    ivec2 step = k == 0 ? ivec2(1, 0) : ivec2(0, 1);
    vec4 a = exit_at(clamp(t + step, ivec2(0), size - 1)), b = exit_at(clamp(t - step, ivec2(0), size - 1));
    bool okA = a.w > 0.0 && distance(a.xyz, e.xyz) < 4.0 * u_layer_texel;
    bool okB = b.w > 0.0 && distance(b.xyz, e.xyz) < 4.0 * u_layer_texel;
    axis[k] = okA && okB ? a.xyz - b.xyz : okA ? a.xyz - e.xyz : okB ? e.xyz - b.xyz : vec3(0.0);
  }
  vec3 n = cross(axis[0], axis[1]);
  float nl = length(n);
  n = nl > 1e-12 ? n / nl : travel;
  n = dot(n, travel) < 0.0 ? -n : n;
  o_exit = vec4(e.xyz * phi, phi);
  o_normal = vec4(n * phi, 0.0);
}
