#include "marble/render/frame_uniforms.h"

#include <glm/gtc/matrix_access.hpp>

namespace marble {

void setFrameUniforms(const gl::Program& p, const CameraMatrices& camera, const LightMatrices& lightM,
                      const Light& light, float lightTexelWorld) {
  p.set("u_inv_view_proj", camera.invViewProj);
  p.set("u_view_proj", camera.viewProj);
  // Its last row, the clip w of a point (its view depth): set once, not rebuilt per pixel.
  p.set("u_view_depth_row", glm::row(camera.viewProj, 3));
  p.set("u_camera_pos", camera.position);
  p.set("u_light_view_proj", lightM.viewProj);
  p.set("u_light_pos", lightM.position);
  p.set("u_light_dir", lightM.direction);
  p.set("u_light_directional", lightM.directional ? 1 : 0);
  p.set("u_light_radiance", light.color * light.intensity);
  p.set("u_light_texel_world", lightTexelWorld);
  // `marble` mode: the point light's intensity is the irradiance (/ pi) at the scene centre, the
  // origin (meshes are centred there; the light's map aims there), and falls off as 1/d^2 around
  // it. The same d0 sets the Cycles reference's light power (tools/cycles_reference.py).
  p.set("u_light_ref_distance", glm::length(light.position));
}

std::string lightKindDefine(bool directional) { return directional ? "LIGHT_DIRECTIONAL 1" : "LIGHT_DIRECTIONAL 0"; }

}  // namespace marble
