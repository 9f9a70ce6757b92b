#version 450 core
// The stage around the object (`marble` mode, issue 19), drawn after the post pass into the
// display image wherever the camera sees no object (G-buffer depth 1):
//   backdrop  the environment seen along the view ray instead of the flat background colour,
//             blurred by u_backdrop_blur (the GGX roughness of the map's prefiltered mips, or the
//             studio's blur angle: the same lookup that gives the stone its reflections);
//   ground    a grey Lambertian floor (albedo 0.18, mid grey) under the object at y = u_ground_y, lit by the
//             key light with the object's shadow (the light's depth map, as on the stone) and by
//             the environment's irradiance for an upward normal times a contact occlusion; it fades
//             into the backdrop (or the background colour) between 2.5 and 6 units from the centre.
// The contact occlusion is an approximation of the floor's ambient occlusion by the object: the
// object's lowest point above each floor point comes from an orthographic map seen from below
// (u_bottom_distance: the height y of the first surface seen from below), and 13 taps in a disk of
// radius 0.5 average exp(-h / 0.18) of the height h of the object above the tap. A soft dark
// pool under the parts that touch or nearly touch the floor, none under parts high above it;
// not a physical visibility integral (it ignores how wide the occluder is).
#include "gbuffer.glsl"
#include "paper_shading.glsl"
#include "deferred_common.glsl"

in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(binding = UNIT_SURFACE_DEPTH) uniform sampler2D u_depth;             // the G-buffer's: 1 where no object
layout(binding = UNIT_STAGE_LIGHT_SHADOW) uniform sampler2DShadow u_light_shadow;
layout(binding = UNIT_STAGE_BOTTOM_DISTANCE) uniform sampler2D u_bottom_distance;  // R32F, nearest

uniform int u_luma_alpha;        // 1: alpha holds the display colour's luma, for FXAA
uniform float u_exposure_scale;  // 2^exposure, as the post pass
uniform vec3 u_background;       // display colour
uniform float u_env_intensity;
uniform int u_env_on;            // 0: environment "none" (no backdrop light)
uniform int u_backdrop;
uniform float u_backdrop_blur;
uniform int u_ground;
uniform float u_ground_y;
uniform mat4 u_bottom_view_proj;

#include "marble_shading.glsl"
#include "environment.glsl"
#include "display.glsl"

const float kGroundAlbedo = 0.18;  // the photographers' mid grey

// The light's shadow on a floor point. A floor point farther from the light than the map's far
// plane lies behind the object: it is compared as if just inside, so it is shadowed exactly
// where the object covers the map.
float ground_visibility(vec3 P) {
  vec3 uvz;
  if (!shadow_lookup(P, vec3(0.0, 1.0, 0.0), u_light_view_proj, u_light_texel_world, uvz)) return 1.0;
  uvz.z = min(uvz.z, 0.99999);
  return texture(u_light_shadow, uvz);
}

// exp(-h / 0.18) of the object's height h above the floor at xz (0 outside the map).
float closeness(vec2 xz) {
  vec4 clip = u_bottom_view_proj * vec4(xz.x, u_ground_y, xz.y, 1.0);
  vec2 uv = clip.xy * 0.5 + 0.5;  // orthographic: w = 1
  float h = max(texture(u_bottom_distance, uv).r - u_ground_y, 0.0);
  return all(lessThanEqual(abs(clip.xy), vec2(1.0))) ? exp(-h / 0.18) : 0.0;
}

// The centre (weight 2), then rings of six at radii 0.2 and 0.5, the outer one turned by 30
// degrees; written out, not looped over an array: llvmpipe indexes arrays lane by lane.
float contact_occlusion(vec3 P) {
  const float a = 0.2, b = 0.1, c = 0.17320508;    // 0.2 (1, 0), 0.2 (cos 60, sin 60)
  const float d = 0.43301270, e = 0.25, f = 0.5;   // 0.5 (cos 30, sin 30), 0.5 (0, 1)
  vec2 p = P.xz;
  float sum = 2.0 * closeness(p) +
              closeness(p + vec2(a, 0.0)) + closeness(p + vec2(b, c)) + closeness(p + vec2(-b, c)) +
              closeness(p + vec2(-a, 0.0)) + closeness(p + vec2(-b, -c)) + closeness(p + vec2(b, -c)) +
              closeness(p + vec2(d, e)) + closeness(p + vec2(0.0, f)) + closeness(p + vec2(-d, e)) +
              closeness(p + vec2(-d, -e)) + closeness(p + vec2(0.0, -f)) + closeness(p + vec2(d, -e));
  return 1.0 - 0.85 * sum / 14.0;
}

vec3 display(vec3 linear) { return srgb_encode(pbr_neutral(linear * u_exposure_scale)); }

void main() {
  if (texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r < 1.0) discard;  // the object: the post pass's
  vec3 nearP = surface_point(v_uv, 0.0), farP = surface_point(v_uv, 1.0);
  vec3 dir = normalize(farP - nearP);
  vec3 behind = u_backdrop == 1 && u_env_on == 1 ? display(u_env_intensity * env_radiance(dir, u_backdrop_blur))
                                                 : u_background;
  vec3 c = behind;
  if (u_ground == 1 && dir.y < -1e-4) {
    float t = (u_ground_y - u_camera_pos.y) / dir.y;
    if (t > 0.0) {
      vec3 P = u_camera_pos + t * dir;
      vec3 N = vec3(0.0, 1.0, 0.0);
      vec3 L = light_vector(P);
      vec3 direct = light_irradiance(light_distance_of(P)) * max(dot(N, L), 0.0) * ground_visibility(P) / PI;
      vec3 ambient = u_env_on == 1 ? u_env_intensity * env_diffuse(N) * contact_occlusion(P) : vec3(0.0);
      vec3 floorColour = display(kGroundAlbedo * (direct + ambient));
      c = mix(floorColour, behind, smoothstep(2.5, 6.0, length(P.xz)));
    }
  }
  c = clamp(c, 0.0, 1.0);
  o_color = vec4(c, u_luma_alpha == 1 ? fxaa_luma(c) : 1.0);
}
