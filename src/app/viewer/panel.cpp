// The viewer's ImGui panel: what the paper's panel had (parameters, colours, a mesh path
// box, the render mode, the frame rate) grouped in collapsible sections with tooltips.
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "marble/mesh/mesh.h"
#include "marble/scene/material_io.h"
#include "viewer_state.h"

namespace marble {
namespace {

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

bool inputText(const char* label, std::string& value) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%s", value.c_str());
  const bool enter = ImGui::InputText(label, buf, sizeof buf, ImGuiInputTextFlags_EnterReturnsTrue);
  value = buf;
  return enter;
}

template <typename Enum>
void enumCombo(const char* label, Enum& value, std::initializer_list<const char*> names, const char* tip) {
  int i = static_cast<int>(value);
  std::vector<const char*> items(names);
  if (ImGui::Combo(label, &i, items.data(), static_cast<int>(items.size()))) value = static_cast<Enum>(i);
  tooltip(tip);
}

void drawStats(ViewerState& s) {
  float avg = 0;
  std::vector<float> v(s.frameMs.begin(), s.frameMs.end());
  for (float f : v) avg += f;
  if (!v.empty()) avg /= static_cast<float>(v.size());
  ImGui::Text("%.1f ms/frame (%.0f FPS)", avg, avg > 0 ? 1000.0f / avg : 0.0f);
  if (!v.empty()) ImGui::PlotLines("##frames", v.data(), static_cast<int>(v.size()), 0, nullptr, 0.0f, std::max(50.0f, avg * 2), ImVec2(0, 40));
  const PassTimes& t = s.passTimes;
  ImGui::Text("GPU: light %.1f  geometry %.1f  lighting %.1f ms", t.lightDepthMs, t.geometryMs, t.lightingMs);
  tooltip("GPU time of each pass (timer queries). Light depth and geometry are re-run only when their inputs change.");
  ImGui::Text("%s, %zu triangles", s.meshLabel.c_str(), s.triangles);
}

void drawMesh(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Mesh")) return;
  if (inputText("path", s.meshPathInput)) s.requestMeshLoad = true;
  tooltip("OBJ, PLY, STL, glTF/GLB. Enter or Load; or drop a file on the window.");
  if (ImGui::Button("Load")) s.requestMeshLoad = true;
  ImGui::SameLine();
  for (const auto& name : builtinMeshNames()) {
    if (ImGui::SmallButton(name.c_str())) {
      s.meshPathInput = "builtin:" + name;
      s.requestMeshLoad = true;
    }
    ImGui::SameLine();
  }
  ImGui::NewLine();
  enumCombo("file up axis", s.scene.up, {"+Y", "+Z", "+X", "-Y", "-Z", "-X"},
            "Which axis of the file points up (many scans are Z-up). Applies on the next load.");
}

void drawTexture(Material& m) {
  if (!ImGui::CollapsingHeader("Texture (paper 3.1)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  enumCombo("mapping", m.mapping, {"planar x/z (paper)", "triplanar", "solid 3D"},
            "Planar: the paper's 2D texture on x/z, stretched along y and mirrored. Solid: the pattern of a block of stone cut into shape.");
  enumCombo("noise", m.basis, {"value (paper)", "Perlin gradient"}, "Smooth-noise basis under the turbulence.");
  int seed = static_cast<int>(m.seed);
  if (ImGui::InputInt("seed", &seed)) m.seed = static_cast<uint32_t>(std::max(0, seed));
  tooltip("Seed of the white-noise lattice: another block of the same stone.");
  ImGui::SliderFloat("x period", &m.x_period, 0.0f, 30.0f);
  tooltip("Vein repetitions along x. With y period: the angle and spacing of the veins. Both 0: turbulence alone.");
  ImGui::SliderFloat("y period", &m.y_period, 0.0f, 30.0f);
  tooltip("Vein repetitions along y (the texture's t).");
  ImGui::SliderFloat("z period", &m.z_period, 0.0f, 30.0f);
  tooltip("Vein repetitions along z (solid mapping).");
  ImGui::SliderFloat("turbulence power", &m.turb_power, 0.0f, 20.0f);
  tooltip("How much the turbulence bends the veins. 0 gives straight sine stripes.");
  ImGui::SliderFloat("turbulence size", &m.turb_size, 1.0f, 128.0f);
  tooltip("Size of the first (largest) octave in texels; each further octave halves it.");
  ImGui::SliderInt("resolution", &m.resolution, 16, 1024);
  tooltip("Texels across the pattern: the lattice density of the white noise.");
  ImGui::SliderFloat("pattern scale", &m.pattern_scale, 0.1f, 8.0f);
  tooltip("Size of the pattern on the object.");
  ImGui::ColorEdit3("base", &m.base_color.x);
  tooltip("Colour of the stone between veins.");
  ImGui::ColorEdit3("vein", &m.vein_color.x);
  tooltip("Colour at the heart of a vein.");
  ImGui::ColorEdit3("vein 2", &m.vein2_color.x);
  tooltip("Secondary vein colour, between base and vein.");
  ImGui::SliderFloat("vein sharpness", &m.vein_sharpness, 0.1f, 8.0f);
  tooltip("Exponent on the sine pattern: higher gives thinner, crisper veins.");
  ImGui::SliderFloat("vein 2 amount", &m.vein2_amount, 0.0f, 1.0f);
  tooltip("How much of the secondary colour the ramp uses.");
}

void drawSubsurface(Material& m) {
  if (!ImGui::CollapsingHeader("Subsurface (paper 3.2)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SliderFloat3("sigma_t", &m.sigma_t.x, 0.0f, 5.0f);
  tooltip("Extinction per scene unit, per RGB channel: exp(-sigma_t * thickness). Red travels further in marble than blue.");
  ImGui::SliderFloat("k_sss", &m.k_sss, 0.0f, 1.0f);
  tooltip("Strength of the subsurface term: 0 = off, 1 = full.");
}

void drawReflectance(Material& m) {
  if (!ImGui::CollapsingHeader("Reflectance (paper 3.3)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SliderFloat("k_schlick", &m.k_schlick, 0.0f, 1.0f);
  tooltip("Opacity of the Fresnel-Schlick reflectance blended over the colour.");
  ImGui::SliderFloat("metalness", &m.metalness, 0.0f, 1.0f);
  tooltip("F0 = mix(0.04, diffuse, metalness): 0 is a dielectric like calcite.");
  enumCombo("order", m.order, {"subsurface first (paper)", "reflectance first"}, "Which term is applied first (paper section 4).");
  enumCombo("Schlick cos", m.schlick_cos, {"H.V (standard)", "H.N (paper)"}, "Angle in (1-cos)^5: the standard form uses H.V.");
  ImGui::SliderFloat("Phong shininess", &m.shininess, 1.0f, 256.0f);
  tooltip("Specular exponent of the Phong comparison mode.");
  ImGui::SliderFloat("Oren-Nayar sigma", &m.oren_nayar_sigma, 0.0f, 1.0f);
  tooltip("Surface roughness (radians) of the Oren-Nayar comparison mode.");
}

void drawLight(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SliderFloat("azimuth", &s.light.yaw_deg, -180.0f, 180.0f);
  tooltip("Angle around the object. Shift+drag or right-drag in the view moves the light too.");
  ImGui::SliderFloat("elevation", &s.light.pitch_deg, -89.0f, 89.0f);
  ImGui::SliderFloat("distance", &s.light.distance, 2.0f, 20.0f);
  tooltip("Distance from the object's centre, in scene units (the object is 2 units across).");
  enumCombo("type", s.scene.light.type, {"point", "directional"}, "A point light at the position, or parallel light from its direction.");
  ImGui::ColorEdit3("colour", &s.scene.light.color.x);
  ImGui::SliderFloat("intensity", &s.scene.light.intensity, 0.0f, 4.0f);
  if (ImGui::Button("Light behind")) s.light = Orbit::fromPosition(-s.camera.position() * 1.2f + glm::vec3(0, 0.5f, 0));
  tooltip("Put the light behind the object, as seen from the camera, to show the subsurface glow.");
}

}  // namespace

void drawPanel(ViewerState& s) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("marble");
  drawStats(s);
  int mode = static_cast<int>(s.scene.render.mode);
  std::vector<const char*> names;
  for (const auto& n : renderModeNames()) names.push_back(n.c_str());
  if (ImGui::Combo("render mode", &mode, names.data(), static_cast<int>(names.size())))
    s.scene.render.mode = static_cast<RenderMode>(mode);
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  tooltip("paper: the paper's combination. marble: our best. phong / oren-nayar: comparisons. The rest show one term or buffer.");
  const auto presets = builtinPresets();
  if (ImGui::BeginCombo("preset", s.presetName.c_str())) {
    for (const auto& p : presets) {
      if (ImGui::Selectable(p.name.c_str(), p.name == s.presetName)) {
        try {
          s.scene.material = loadPreset(p.name);
          s.presetName = p.name;
          s.setStatus("preset " + p.name);
        } catch (const std::exception& e) {
          s.setError(e.what());
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.description.c_str());
    }
    ImGui::EndCombo();
  }
  drawMesh(s);
  drawTexture(s.scene.material);
  drawSubsurface(s.scene.material);
  drawReflectance(s.scene.material);
  drawLight(s);
  if (ImGui::Button("Screenshot (F12)")) s.requestScreenshot = true;
  ImGui::SameLine();
  if (ImGui::Button("Help (F1)")) s.showHelp = !s.showHelp;
  if (!s.status.empty()) {
    if (s.statusIsError) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", s.status.c_str());
    if (s.statusIsError) ImGui::PopStyleColor();
  }
  ImGui::End();
}

void drawHelpOverlay(ViewerState& s) {
  const ImVec2 ds = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(ds.x * 0.5f, ds.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Help", &s.showHelp, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(
      "Left drag           orbit the camera\n"
      "Wheel               zoom\n"
      "Middle drag         pan\n"
      "Shift+drag, right   move the light around the object\n"
      "F                   frame the object (reset view)\n"
      "F12                 screenshot (PNG, unique name)\n"
      "F1 or ?             this help\n"
      "R                   reload shaders (--dev)\n"
      "Drop a file         load it as the mesh\n"
      "Escape              quit");
  ImGui::End();
}

}  // namespace marble
