// Where the light is, and the distance the light's maps store (one definition for the light's
// passes, light_depth.frag.glsl and light_layers.frag.glsl, and the screen passes that read their
// maps, through deferred_common.glsl): from a point light the distance to it, from a directional
// light the distance along its travel.
uniform vec3 u_light_pos;       // point light: its position
uniform vec3 u_light_dir;       // directional light: unit vector the light travels along
// The light's kind: a constant of the program where the pass compiles one per kind (LIGHT_DIRECTIONAL
// 0 or 1: the lighting and post passes, the bounce pass's two gathers), so that llvmpipe, which runs
// both sides of every select and branch, does not pay for the other kind's light vector and
// distance at every call (the dragon's 800^2 camera frame 23.9 M instructions fewer, the pictures
// byte-equal; docs/performance.md, "Thirtieth session: ... s30-cost"); a uniform in the other passes.
#ifdef LIGHT_DIRECTIONAL
const int u_light_directional = LIGHT_DIRECTIONAL;
#else
uniform int u_light_directional;
#endif

// Unit vector from P toward the light.
vec3 light_vector(vec3 P) {
  return u_light_directional == 1 ? -u_light_dir : normalize(u_light_pos - P);
}

// Distance along the light's path: from a point light, or along a directional light.
float light_distance_of(vec3 p) {
  return u_light_directional == 1 ? dot(p, u_light_dir) : distance(p, u_light_pos);
}
