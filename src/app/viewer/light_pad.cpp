// The light direction pad: the sky seen from straight above. The centre is the zenith, the
// inner circle the horizon, the outer ring below it; the angle around is the azimuth. The
// camera's direction is drawn too, so "behind the object" is obvious at a glance.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "panel_sections.h"

namespace marble::viewer {
namespace {

// Elevation 90 -> centre, 0 -> horizon circle (radius r/2... scaled), -89 -> outer rim.
ImVec2 toPad(float yawDeg, float pitchDeg, ImVec2 centre, float radius) {
  const float rho = (90.0f - pitchDeg) / 180.0f * radius;
  const float yaw = glm::radians(yawDeg);
  // +x to the right, +z (towards the default camera) downwards: a map of the floor.
  return ImVec2(centre.x + rho * std::sin(yaw), centre.y + rho * std::cos(yaw));
}

}  // namespace

void lightPad(const char* id, Orbit& light, const Orbit& camera, float size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, ImVec2(size, size));
  const float radius = size * 0.5f - 2.0f;
  const ImVec2 centre(origin.x + size * 0.5f, origin.y + size * 0.5f);
  if (ImGui::IsItemActive()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const float dx = m.x - centre.x, dy = m.y - centre.y;
    const float rho = std::min(std::sqrt(dx * dx + dy * dy), radius);
    light.pitch_deg = std::clamp(90.0f - rho / radius * 180.0f, -89.0f, 89.0f);
    if (rho > 1.0f) light.yaw_deg = glm::degrees(std::atan2(dx, dy));
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Light direction seen from above: centre = overhead, circle = horizon,\n"
                      "outer ring = below. Yellow: light. Blue: camera. Click or drag to move.");
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddCircleFilled(centre, radius, IM_COL32(30, 32, 40, 255), 48);
  dl->AddCircleFilled(centre, radius * 0.5f, IM_COL32(52, 58, 74, 255), 48);  // above the horizon
  dl->AddCircle(centre, radius * 0.5f, IM_COL32(120, 130, 150, 255), 48);
  dl->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), IM_COL32(70, 76, 90, 255));
  dl->AddLine(ImVec2(centre.x, centre.y - radius), ImVec2(centre.x, centre.y + radius), IM_COL32(70, 76, 90, 255));
  const ImVec2 cam = toPad(camera.yaw_deg, camera.pitch_deg, centre, radius);
  dl->AddCircleFilled(cam, 4.0f, IM_COL32(90, 160, 255, 255));
  const ImVec2 l = toPad(light.yaw_deg, light.pitch_deg, centre, radius);
  dl->AddLine(centre, l, IM_COL32(255, 210, 80, 160), 1.5f);
  dl->AddCircleFilled(l, 6.0f, IM_COL32(255, 210, 80, 255));
}

}  // namespace marble::viewer
