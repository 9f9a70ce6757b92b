#version 450 core
// Pass 1 (paper §3, GPU Gems 1 ch. 16.3): the mesh seen from the light. We store the
// world-space distance from the light to the first surface it hits, so the lighting pass
// gets thickness in scene units rather than in non-linear depth-buffer values. Beside it, the
// cosine between that surface's normal and the direction to the light: how much of the light
// enters the stone there (translucent shadow maps, Dachsbacher & Stamminger 2003, store the
// entering irradiance with the depth; the lighting pass applies the Fresnel factor and the light's
// falloff). |cos|: open meshes draw both faces, files wound inward must still let light in, and
// an interpolated normal can turn from the light on a face that faces it.
//
// And a reflective shadow map (Dachsbacher & Stamminger 2005) for the `marble` mode's one
// diffuse bounce (bounce.glsl): every texel's first surface is lit, so it re-emits, as a
// Lambertian surface, flux = albedo x E(d) x w with w = (its area) x cos x principled_entry(cos):
// the light that entered there and leaves again near where it entered (the blur's millimetres are
// small against the bounce's distances). E(d), the light's falloff, and the albedo are applied
// where the map is read, so the map depends on the mesh and the light's matrices only. Stored
// weighted by w (position x w, w) so that the mipmaps (LightDepthPass) average the surface and
// leave out the texels that saw nothing (w = 0); the normal faces the light. Beside the normal,
// a = (its area) x cos x (1 - cos)^5, Schlick's grazing term of the light the surface reflects
// (bounce.glsl: the glossy emitters; area x cos = w + a / 2, so the gather forms the Fresnel
// factor F0 + (1 - F0)(1 - cos)^5 from w and a with the stone's F0).
#include "principled_entry.glsl"
in vec3 v_world_pos;
in vec3 v_world_normal;
#include "light_geometry.glsl"
layout(location = 0) out vec2 o_distance_cos;  // distance, entry cosine
layout(location = 1) out vec4 o_bounce_position;  // world position x w, w (scene units^2)
layout(location = 2) out vec4 o_bounce_normal;    // unit normal toward the light, a (scene units^2)

void main() {
  vec3 toLight = light_vector(v_world_pos);
  float d = light_distance_of(v_world_pos);
  vec3 n = normalize(v_world_normal);
  float c = dot(n, toLight);
  o_distance_cos = vec2(d, abs(c));
  n = c < 0.0 ? -n : n;
  // The surface area this texel covers: exact for a triangle's plane (the derivatives are the
  // texel's edges on it).
  float area = length(cross(dFdx(v_world_pos), dFdy(v_world_pos)));
  float w = area * abs(c) * principled_entry(abs(c));
  float m = 1.0 - abs(c), m2 = m * m;
  o_bounce_position = vec4(v_world_pos * w, w);
  o_bounce_normal = vec4(n, area * abs(c) * (m2 * m2 * m));
}
