#version 450 core
// Pass 3 (paper §3, §3.2, §3.3, §4): full screen. Reads the G-buffer and the light's
// distance map and produces the render mode's picture.
#include "gbuffer.glsl"
#include "paper_shading.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 o_color;
// `marble` only: light that entered the stone (diffuse irradiance / PI, before albedo), for
// the screen-space subsurface blur; o_color then holds what the surface reflects (specular).
layout(location = 1) out vec4 o_diffuse;

layout(binding = 0) uniform sampler2D u_albedo;
layout(binding = 1) uniform sampler2D u_normal;
layout(binding = 2) uniform sampler2D u_depth;
layout(binding = 3) uniform sampler2D u_light_distance;
layout(binding = 4) uniform sampler2DShadow u_light_shadow;

uniform mat4 u_inv_view_proj;
uniform vec3 u_camera_pos;
uniform vec2 u_camera_near_far;
uniform mat4 u_light_view_proj;
uniform vec3 u_light_pos;
uniform vec3 u_light_dir;
uniform int u_light_directional;
uniform vec2 u_light_near_far;   // range of distances the light's map can hold
uniform vec3 u_light_radiance;   // colour x intensity

uniform vec3 u_sigma_t;          // extinction per scene unit, per channel
uniform float u_k_sss;
uniform float u_k_schlick;
uniform float u_metalness;
uniform int u_reflectance_first;
uniform int u_schlick_hn;
uniform float u_shininess;
uniform float u_oren_nayar_sigma;
uniform int u_mode;

// Physically based marble (mode `marble`).
uniform float u_mm_per_unit;     // millimetres per scene unit
uniform vec3 u_sigma_tr_mm;      // effective transport coefficient per mm, sqrt(3 sigma_a sigma_t')
uniform float u_ior;
uniform float u_roughness;
uniform float u_translucency;
uniform float u_env_intensity;   // 0 = no environment light
uniform float u_light_texel_world;  // world size of one light-map texel at the object

// Keep in step with marble::RenderMode.
const int MODE_PAPER = 0, MODE_MARBLE = 1, MODE_PHONG = 2, MODE_OREN_NAYAR = 3, MODE_SUBSURFACE = 4,
          MODE_REFLECTANCE = 5, MODE_ALBEDO = 6, MODE_LIGHT_DEPTH = 7, MODE_THICKNESS = 8,
          MODE_DEPTH = 9, MODE_POSITION = 10, MODE_NORMAL = 11;

float light_distance_of(vec3 p) {
  return u_light_directional == 1 ? dot(p, u_light_dir) : distance(p, u_light_pos);
}

// Distance the light travelled inside the object before leaving at p (GPU Gems 1, 16.3):
// the light's map holds where it entered; p is where it leaves.
float thickness_at(vec3 p) {
  vec4 clip = u_light_view_proj * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 0.0;
  float entered = texture(u_light_distance, ndc.xy * 0.5 + 0.5).r;
  return max(light_distance_of(p) - entered, 0.0);
}

#include "marble_shading.glsl"
#include "environment.glsl"

// The `marble` mode: linear HDR radiance. Light intensity 1 is scaled by PI so a white
// Lambertian surface facing the light reflects 1.0, as in the paper's modes.
void marble_radiance(vec3 P, vec3 N, vec3 V, vec3 L, out vec3 entering, out vec3 reflected) {
  float NoL = dot(N, L);
  float NoV = max(dot(N, V), 1e-4);
  vec3 H = normalize(V + L);
  float a = max(u_roughness * u_roughness, 0.002);
  vec3 F0 = f0_from_ior(u_ior);
  vec3 E = u_light_radiance * PI;
  float visible = pcf_visibility(P, N, u_light_view_proj, u_light_texel_world);

  float nl = max(NoL, 0.0);
  vec3 F = fresnel_schlick(F0, dot(H, V));
  vec3 specular = ggx_distribution(max(dot(N, H), 0.0), a) * smith_ggx_visibility(NoV, nl, a) * F;
  // Energy split: light that is reflected at the surface, on the way in or out, does not
  // enter the stone (Shirley et al. 1997's coupled diffuse, in Schlick form).
  vec3 into = (1.0 - fresnel_schlick(F0, nl)) * (1.0 - fresnel_schlick(F0, NoV));
  vec3 diffuse = into / PI;

  // Transmission: light that entered where the light's map says and crossed s millimetres of
  // stone to leave here, attenuated per channel by exp(-sigma_tr s) (Jensen et al. 2001's
  // diffusion decay). An inward offset keeps the surface's own depth sample out (no acne).
  // It reaches the side facing away from the light; facing the light, the direct term
  // already carries that light (weight after Barre-Brisebois & Bouchard 2011).
  float s_mm = thickness_at(P - N * (2.0 * u_light_texel_world)) * u_mm_per_unit;
  float away = clamp(0.5 - 0.5 * NoL, 0.0, 1.0);
  vec3 transmitted = E / PI * exp(-u_sigma_tr_mm * s_mm) * away * away * u_translucency *
                     (1.0 - fresnel_schlick(F0, NoV));

  entering = E * nl * visible * diffuse + transmitted;
  reflected = E * nl * visible * specular;
  if (u_env_intensity > 0.0) {
    vec3 R = reflect(-V, N);
    entering += u_env_intensity * env_diffuse(N) * (1.0 - fresnel_schlick(F0, NoV));
    reflected += u_env_intensity * env_radiance(R, u_roughness) * env_brdf_approx(F0, u_roughness, NoV);
  }
}

void main() {
  o_diffuse = vec4(0.0);
  if (u_mode == MODE_LIGHT_DEPTH) {
    // The light's distance map itself, near = black, far (nothing hit) = white.
    float d = texture(u_light_distance, v_uv).r;
    float t = clamp((d - u_light_near_far.x) / (u_light_near_far.y - u_light_near_far.x), 0.0, 1.0);
    o_color = vec4(vec3(t), 1.0);
    return;
  }
  float depth = texture(u_depth, v_uv).r;
  if (depth >= 1.0) {
    // No surface: zero light (the linear HDR image and --hdr keep 0 there); the post pass
    // paints the background colour.
    o_color = vec4(0.0);
    return;
  }
  vec4 world = u_inv_view_proj * vec4(vec3(v_uv, depth) * 2.0 - 1.0, 1.0);
  vec3 P = world.xyz / world.w;
  vec3 N = decode_normal(texture(u_normal, v_uv).xy);
  vec3 albedo = texture(u_albedo, v_uv).rgb;
  vec3 V = normalize(u_camera_pos - P);
  vec3 L = u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - P);

  vec3 c;
  if (u_mode == MODE_MARBLE) {
    vec3 entering;
    marble_radiance(P, N, V, L, entering, c);
    o_diffuse = vec4(entering, 1.0);
  } else if (u_mode == MODE_PAPER) {
    vec3 sss = paper_subsurface(u_sigma_t * thickness_at(P), u_k_sss) * u_light_radiance;
    if (u_reflectance_first == 0) {
      // Paper §4: subsurface first, its result is the Schlick input colour.
      vec3 d = albedo * sss;
      c = mix(d, paper_schlick(d, u_metalness, N, V, L, u_schlick_hn), u_k_schlick);
    } else {
      c = mix(albedo, paper_schlick(albedo, u_metalness, N, V, L, u_schlick_hn), u_k_schlick) * sss;
    }
  } else if (u_mode == MODE_PHONG) {
    c = phong(albedo, N, V, L, u_light_radiance, u_shininess);
  } else if (u_mode == MODE_OREN_NAYAR) {
    c = oren_nayar(albedo, N, V, L, u_light_radiance, u_oren_nayar_sigma);
  } else if (u_mode == MODE_SUBSURFACE) {
    c = albedo * paper_subsurface(u_sigma_t * thickness_at(P), u_k_sss);
  } else if (u_mode == MODE_REFLECTANCE) {
    c = paper_schlick(albedo, u_metalness, N, V, L, u_schlick_hn);
  } else if (u_mode == MODE_ALBEDO) {
    c = albedo;
  } else if (u_mode == MODE_THICKNESS) {
    // 0 = black; 2*sqrt(3) scene units (the longest chord of the normalized mesh's
    // bounding sphere, kThicknessViewRange) = white.
    c = vec3(thickness_at(P) / 3.4641016);
  } else if (u_mode == MODE_DEPTH) {
    float dist = distance(P, u_camera_pos);
    c = vec3(clamp((dist - u_camera_near_far.x) / (u_camera_near_far.y - u_camera_near_far.x), 0.0, 1.0));
  } else if (u_mode == MODE_POSITION) {
    c = clamp(P * 0.5 + 0.5, 0.0, 1.0);
  } else {
    c = N * 0.5 + 0.5;
  }
  o_color = vec4(c, 1.0);
}
