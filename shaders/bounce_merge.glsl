// The bounce pass's merge (bounce_merge.frag.glsl on its grid, bounce_refine_merge.comp.glsl on
// the refined texels): a texel's first bounce b (bounce_gather) and the further bounces bF
// brought to it (bounce_further.frag.glsl's grid, upsampled), with the emitters' albedo and
// Fresnel factors applied once per texel here rather than once per lighting texel.
// Needs from the includer: fresnel_f0.glsl.
uniform vec3 u_pat_base_color;  // the stone's albedo between veins: the emitters' albedo
uniform float u_ior;            // the emitters' Fresnel F0 (their glossy reflection)

// rgb: irradiance / PI of all bounces per unit of the light's radiance, the emitters' albedo and
// Fresnel factors applied; a: the first bounce's mirrored part as it was (b.a >= 0: a surface).
vec4 bounce_merged(vec4 b, vec4 bF) {
  vec3 A = u_pat_base_color;
  // The first bounce's scalars (bounce.glsl): diffuse x albedo, glossy x Schlick's F split by F0.
  float F0 = f0_from_ior(u_ior).x;
  // The further bounces: the second, albedo x (the first's terms over the emitters the camera
  // sees), and the rest by the series 1 / (1 - albedo F), F the view factor of that stone (at most
  // 0.8: a point can see no more than its hemisphere, and the floor keeps the series finite where
  // the coarse sums overshoot).
  vec3 second = A * (A * bF.x + F0 * bF.y + (1.0 - F0) * bF.z);
  vec3 further = second / (1.0 - A * (41.0 / 42.0) * min(bF.a, 0.8));
  return vec4(A * b.x + F0 * b.y + (1.0 - F0) * b.z + further, b.a);
}
