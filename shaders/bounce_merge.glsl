// The bounce pass's merge (bounce_merge.frag.glsl on its grid, bounce_refine_merge.comp.glsl on
// the refined texels): a texel's first bounce b (bounce_gather) and the further bounces at its
// surface point (the radiosity's grid, further_radiosity.h), with the emitters' albedo and Fresnel
// factors applied once per texel here rather than once per lighting texel.
// Needs from the includer: gbuffer.glsl (the units), fresnel_f0.glsl.
uniform vec3 u_pat_base_color;  // the stone's albedo between veins: the emitters' albedo
uniform float u_ior;            // the emitters' Fresnel F0 (their glossy reflection)
// The further bounces' albedo-free terms, premultiplied by the cells' weight:
// (w G_2 / PI, w G_3 / PI, w G_4 / PI, w), read trilinearly (GL_LINEAR) and divided by the weight
// (a normalised convolution: the empty cells around the surface drop out).
layout(binding = UNIT_LIGHTING_BOUNCE_FURTHER) uniform sampler3D u_further_grid;
uniform mat4 u_further_from_world;  // world space to the grid's texture coordinates

// The second to fourth bounces' irradiance / PI at the world point P per unit of the light's
// radiance: the n-th arrives as A^n w^(2n-1) G_n (w = 41/42: an emitter's (1 - F/2) over a
// cosine-weighted hemisphere, on the way in and out; A its albedo), and the receiver takes diffuse
// light in at w too: w (A^2 w^3 G_2 + A^3 w^5 G_3 + A^4 w^7 G_4).
vec3 further_bounces(vec3 P) {
  vec4 g = textureLod(u_further_grid, (u_further_from_world * vec4(P, 1.0)).xyz, 0.0);
  if (g.a <= 0.0) return vec3(0.0);
  const float w = 41.0 / 42.0;
  vec3 Aw2 = u_pat_base_color * (w * w);
  return Aw2 * Aw2 * (g.r + Aw2 * (g.g + Aw2 * g.b)) / g.a;
}

// rgb: irradiance / PI of all bounces per unit of the light's radiance, the emitters' albedo and
// Fresnel factors applied; a: the first bounce's mirrored part as it was (b.a >= 0: a surface).
vec4 bounce_merged(vec4 b, vec3 P) {
  vec3 A = u_pat_base_color;
  // The first bounce's scalars (bounce.glsl): diffuse x albedo, glossy x Schlick's F split by F0.
  float F0 = f0_from_ior(u_ior).x;
  return vec4(A * b.x + F0 * b.y + (1.0 - F0) * b.z + further_bounces(P), b.a);
}
