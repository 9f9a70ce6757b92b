#pragma once
// The light's map as the transmission chord's compute tests stand it in (transmission_chord_gl_test,
// chord_footprint_gl_test): the light travels along +z, so a point's distance from it is its z and
// the map's normalized coordinates its x and y (u_light_view_proj the identity); the map at unit 0.
namespace marble::test {

inline constexpr const char* kLightAlongZ = R"(
layout(binding = 0) uniform sampler2D u_light_distance;
uniform mat4 u_light_view_proj;
uniform float u_light_texel_world;
uniform vec2 u_light_near_far;
float light_distance_of(vec3 p) { return p.z; }
)";

}  // namespace marble::test
