// Light from around the object for the `marble` mode, one of two kinds (ENV_KIND, below):
// the procedural studio (marble_shading.glsl, no file needed) or an equirectangular map,
// prefiltered on the CPU once per load (src/marble/environment/). Both give
//   env_diffuse(n):             irradiance / PI for a surface facing n
//   env_radiance(dir, roughness): radiance seen looking along dir, blurred by a GGX lobe of that roughness
// Needs from the includer: PI, studio_diffuse(), studio_radiance().

layout(binding = UNIT_ENV_MAP) uniform sampler2D u_env_map;  // mip k >= 1: GGX-prefiltered for alpha_1 2^(k-1)
// The kind is a constant of the program (ENV_KIND, defined by the passes that include this;
// gl/program_variants.h): llvmpipe would run the map's lookups for the studio too.
#ifdef ENV_KIND
const int u_env_kind = ENV_KIND;
#else
uniform int u_env_kind;        // ENV_STUDIO or ENV_MAP
#endif
uniform vec3 u_env_sh[9];      // E(n) / PI as a polynomial in n (src/marble/environment/sh_irradiance.h)
uniform vec2 u_env_rotation;   // cos and sin of the map's yaw about +Y
uniform float u_env_alpha1;    // GGX alpha of mip level 1 (level 0 is the map itself)
uniform float u_env_max_lod;
// The studio's blur angle for the frame's roughness (1.2 roughness), as cos and sin: set with
// the roughness by the pass that calls env_radiance (marble::setStudioBlurUniform).
uniform vec2 u_studio_blur_cs;

const float kStudioBlurPerRoughness = 1.2;  // the same constant in render/environment_map.h

// A world direction in the map's own frame: the map is turned by +yaw about +Y, so it is looked
// up along R_y(-yaw) d.
vec3 env_map_direction(vec3 d) {
  float c = u_env_rotation.x, s = u_env_rotation.y;
  return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// Equirectangular mapping, the same as src/marble/environment/equirect.h: the image centre looks
// along -Z, +X is right of it, the top row is +Y. (The tiny offset keeps atan defined at the poles.)
vec2 env_equirect_uv(vec3 d) {
  return vec2(0.5 + atan(d.x, -d.z + 1e-30) * (0.5 / PI), acos(clamp(d.y, -1.0, 1.0)) / PI);
}

vec3 env_diffuse(vec3 n) {
  if (u_env_kind == ENV_STUDIO) return studio_diffuse(n);
  // Ramamoorthi and Hanrahan 2001, eq. 13, regrouped (and divided by PI) on the CPU.
  vec3 d = env_map_direction(n);
  vec3 e = u_env_sh[0] + u_env_sh[1] * d.x + u_env_sh[2] * d.y + u_env_sh[3] * d.z +
           u_env_sh[4] * (d.x * d.y) + u_env_sh[5] * (d.y * d.z) + u_env_sh[6] * (d.x * d.z) +
           u_env_sh[7] * (d.z * d.z) + u_env_sh[8] * (d.x * d.x - d.y * d.y);
  return max(e, vec3(0.0));  // the order-2 fit of a very contrasted map can ring below zero
}

vec3 env_radiance(vec3 dir, float roughness) {
  if (u_env_kind == ENV_STUDIO) return studio_radiance(dir, roughness * kStudioBlurPerRoughness, u_studio_blur_cs);
  // Level k holds alpha_1 2^(k-1); below alpha_1 / 2 the map itself is as sharp as it gets.
  float alpha = max(roughness * roughness, 1e-8);
  float lod = clamp(1.0 + log2(alpha / u_env_alpha1), 0.0, u_env_max_lod);
  return textureLod(u_env_map, env_equirect_uv(env_map_direction(dir)), lod).rgb;
}
