// The light's visibility for the light entering the stone (marble_entering): percentage-closer
// filtering (Reeves et al. 1987) of the light's distance map, each texel compared with the receiver's
// own tangent plane (a receiver-plane depth test: Isidoro 2006, "Shadow mapping: GPU-based tips and
// techniques", GDC).
//
// Needs from the includer: u_light_distance (the light's map: .r the distance from the light to the
// first surface, light_depth.frag.glsl), u_light_view_proj, u_light_near_far, light_vector,
// light_distance_of, u_light_directional (light_geometry.glsl).
//
// The filter is the one the hardware comparison gave before session 25: four bilinear taps at
// +-0.5 texel around P's place in the map, 16 texels in all. What changed is what each texel is
// compared with. Before, every texel was compared with P's own distance, pushed toward the light by
// the slope-scaled bias 2 texels x tan(theta) (+ half a texel along N), theta the angle between N and
// the light: on a surface the light grazes, the plane itself recedes by up to 1.5 texels x tan(theta)
// across the filter, so that bias was both too much (an occluder on the far side of the filter had
// to stand 3.5 texels x tan(theta) in front of the surface to count) and too little (on the near
// side 0.5). Now each texel's distance is compared with where *its own* ray from the light meets P's
// tangent plane, so the slope is taken out of every comparison exactly, and the same bias,
// 2 texels x tan(theta) + half a texel, is what is left for the surface's bend within the filter
// and for the mesh's facets, which tilt against the interpolated normal (a bias that does not
// grow at grazing light, 2 to 8 texels, self-shadows the teapot's 1024 facets: teapot-side SSIM
// -0.0013 to -0.007; docs/quality.md, "Twenty-fifth session"). Against Cycles' visibility of a white
// Lambert in the side-lit scenes this moves marble's by 0.004-0.017 toward Cycles' where N.L < 0.3
// (where the old lookup let through 0.05-0.13 more light than Cycles' occluders; the rest needs a
// bias the facets do not allow) and by 0.001-0.003 on the lit faces.
//
// Texels whose ray met nothing (the map's far value) are lit; where P is outside the map nothing is
// in the way (as shadow_lookup). The rays through the texels: P's place in the map moved by the
// texel offset, mapped back onto the plane through P across the light (J, the projection's
// Jacobian there, by differences over a texel: its error second order in the offset, 1.5 texels).
vec2 light_map_texel_coord(vec3 p, vec2 size) {
  vec4 clip = u_light_view_proj * vec4(p, 1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * size - 0.5;  // texel k's centre at k
}

float receiver_plane_visibility(vec3 P, vec3 N, float texel_world) {
  vec2 size = vec2(textureSize(u_light_distance, 0));
  vec4 clip = u_light_view_proj * vec4(P, 1.0);
  if (any(greaterThan(abs(clip.xy / clip.w), vec2(1.0)))) return 1.0;
  vec3 L = light_vector(P);
  vec3 e1 = normalize(cross(L, abs(L.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 e2 = cross(L, e1);
  vec2 t0 = light_map_texel_coord(P, size);
  mat2 J = mat2(light_map_texel_coord(P + texel_world * e1, size) - t0,
                light_map_texel_coord(P + texel_world * e2, size) - t0) / texel_world;
  // A texel offset o from P's place in the map is the point Q = P + a.x e1 + a.y e2, a = J^-1 o, on
  // the plane through P across the light; Q lies s = N.(Q - P) = g.o above P's tangent plane. The
  // ray through Q meets that plane at the distance D + s / c along a directional light (D = P's
  // distance as the map stores it, light_distance_of; c = N.L), and at |Q - light| c D / (c D - s)
  // from a point light, |Q - light| = sqrt(D^2 + |a|^2) taken as D (|a| <= 1.5 texels: at most
  // 3e-6 units at the references' 4.6 units); beyond the plane's horizon (s >= c D), very far.
  vec2 g = transpose(inverse(J)) * vec2(dot(N, e1), dot(N, e2));
  float c = dot(N, L);
  float D = light_distance_of(P);
  float cb = clamp(c, 0.05, 1.0);
  float bias = texel_world * (2.0 * sqrt(1.0 - cb * cb) / cb + 0.5);
  const vec2 corner[4] = vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(1.0, 0.0), vec2(0.0, 0.0));  // textureGather's order
  float lit = 0.0;
  for (int k = 0; k < 4; ++k) {
    vec2 tap = t0 + vec2((k & 1) == 0 ? -0.5 : 0.5, (k & 2) == 0 ? -0.5 : 0.5);
    vec2 base = floor(tap);
    vec2 f = tap - base;
    vec4 stored = textureGather(u_light_distance, (base + 1.0) / size, 0);
    vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    for (int i = 0; i < 4; ++i) {
      float s = dot(g, base + corner[i] - t0);
      float receiver = u_light_directional == 1 ? (c > 1e-4 ? D + s / c : 1e30)
                                                : (c * D - s > 1e-6 ? D * D * c / (c * D - s) : 1e30);
      bool nothing = stored[i] > u_light_near_far.y + 1.0;
      lit += w[i] * ((nothing || stored[i] >= receiver - bias) ? 1.0 : 0.0);
    }
  }
  return lit * 0.25;
}
