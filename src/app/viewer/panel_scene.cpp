// The panel's non-material sections: files, mesh, light, view.
#include <algorithm>
#include <filesystem>
#include <functional>

#include "marble/mesh/mesh.h"
#include "marble/scene/material_io.h"
#include "marble/scene/placement.h"
#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble::viewer {

void drawTopBar(ViewerState& s) {
  if (ImGui::BeginCombo("preset", s.presetName.c_str())) {
    for (const auto& p : builtinPresets()) {
      if (ImGui::Selectable(p.name.c_str(), p.name == s.presetName)) {
        try {
          s.scene.material = loadPreset(p.name);
          s.presetName = p.name;
          s.presetMaterial = s.scene.material;
          s.setStatus("preset " + p.name + " (Ctrl+Z goes back)");
        } catch (const std::exception& e) {
          s.setError(e.what());
        }
      }
      tooltip(p.description.c_str());
    }
    ImGui::EndCombo();
  }
  tooltip("Built-in marbles. Picking one replaces the whole material (undoable).\n"
          "Files: load your own in the Files section.");
  enumCombo("render mode", s.scene.render.mode, renderModeChoices(),
            "marble: our best. paper: the paper's combination. phong / oren-nayar: comparisons.\n"
            "subsurface, reflectance: one term alone. albedo ... normal: the buffers. floor: the mesh once, flat (the benchmarks' floor).");
  if (s.scene.render.mode == RenderMode::Marble) {
    bool fullBlur = s.scene.render.subsurface_resolution == SubsurfaceResolution::Full;
    if (ImGui::Checkbox("full-resolution blur", &fullBlur))
      s.scene.render.subsurface_resolution = fullBlur ? SubsurfaceResolution::Full : SubsurfaceResolution::Half;
    tooltip("The subsurface blur at full resolution: slightly crisper shading, about 4x the blur's cost.\n"
            "Off: half resolution, for fast interaction.");
  }
  ImGui::BeginDisabled(!s.undo.canUndo());
  if (ImGui::Button("Undo")) s.requestUndo = true;
  ImGui::EndDisabled();
  tooltip("Ctrl+Z: undo the last parameter change (material, light, render mode).");
  ImGui::SameLine();
  ImGui::BeginDisabled(!s.undo.canRedo());
  if (ImGui::Button("Redo")) s.requestRedo = true;
  ImGui::EndDisabled();
  tooltip("Ctrl+Y or Ctrl+Shift+Z.");
  ImGui::SameLine();
  ImGui::TextDisabled("%zu / %zu steps", s.undo.undoCount(), s.undo.redoCount());
  ImGui::SameLine();
  if (ImGui::Button("Help")) s.showHelp = !s.showHelp;
  tooltip("F1 or ?: every shortcut.");
  // The frame time at a glance, without scrolling to the Performance section.
  if (!s.frameMs.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%.0f ms/frame", s.frameMs.back());
    tooltip("Last frame's time; the Performance section has the graph and each pass's GPU time.");
  }
}

void drawFilesSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Files")) return;
  inputText("material##path", s.materialPathInput, "preset.json or a preset name");
  tooltip("A material preset file (JSON, the keys of docs/materials.md), or a built-in preset's name for Load.");
  if (ImGui::Button("Save material")) s.requestSaveMaterial = true;
  tooltip("Writes the current material to the path (atomically: an old file is never left half-written).");
  ImGui::SameLine();
  if (ImGui::Button("Load material")) s.requestLoadMaterial = true;
  tooltip("Replaces the material; a bad file shows its error below and changes nothing.");
  inputText("scene##path", s.scenePathInput, "scene.json");
  tooltip("A whole scene: mesh, camera, light, material, render settings (docs/scene-format.md).");
  if (ImGui::Button("Save scene")) s.requestSaveScene = true;
  tooltip("Writes everything you see to the path (atomically). `marble render SCENE -o out.png` renders it.");
  ImGui::SameLine();
  if (ImGui::Button("Load scene")) s.requestLoadScene = true;
  tooltip("Replaces everything (and clears undo); a bad file or mesh shows its error and changes nothing.");
}

void drawMeshSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Mesh")) return;
  ImGui::TextWrapped("%s, %zu triangles", s.meshLabel.c_str(), s.triangles);
  if (inputText("path##mesh", s.meshPathInput, "model.obj - or drop a file")) s.requestMeshLoad = true;
  tooltip("OBJ, PLY, STL, glTF/GLB. Enter or Load; or drop a file on the window.\nA bad file keeps the current mesh.");
  if (ImGui::Button("Load")) s.requestMeshLoad = true;
  ImGui::TextUnformatted("built-in:");
  for (const auto& name : builtinMeshNames()) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(name.c_str()).x + 12) ImGui::NewLine();
    if (ImGui::SmallButton(name.c_str())) {
      s.meshPathInput = "builtin:" + name;
      s.requestMeshLoad = true;
    }
  }
  if (enumCombo("file up axis", s.scene.up, {"+Y", "+Z", "+X", "-Y", "-Z", "-X"},
                "Which axis of this file points up (many scans, like the paper's dragon, are Z-up).\n"
                "Reloads and frames the mesh. Each file keeps its own: a new file starts at +Y."))
    if (s.scene.mesh.rfind("builtin:", 0) != 0) {
      s.meshPathInput = s.scene.mesh;
      s.requestMeshLoad = true;
    }
}

namespace {
// A row of small buttons, one per preset, after a label.
void presetButtons(const char* label, const std::vector<Placement>& presets,
                   const std::function<void(const Placement&)>& apply, const char* tip) {
  ImGui::TextUnformatted(label);
  for (const auto& p : presets) {
    ImGui::SameLine();
    ImGui::PushID(label);
    if (ImGui::SmallButton(p.name)) apply(p);
    ImGui::PopID();
    tooltip(tip);
  }
}
}  // namespace

void drawLightSection(ViewerState& s) {
  bool reset;
  const bool open = sectionHeader("Light", true, "Put the light back where the scene had it.", reset);
  if (reset) {
    s.scene.light = s.initialLight;
    s.light = s.initialLightOrbit;
  }
  if (!open) return;
  const float pad = 96.0f * ImGui::GetIO().FontGlobalScale;
  lightPad("##lightpad", s.light, s.camera, pad);
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::PushItemWidth(-80.0f * ImGui::GetIO().FontGlobalScale);
  ImGui::SliderFloat("azimuth", &s.light.yaw_deg, -180.0f, 180.0f, "%.0f deg");
  tooltip("Angle around the object. Shift+drag or right-drag in the view moves the light too.");
  ImGui::SliderFloat("elevation", &s.light.pitch_deg, -89.0f, 89.0f, "%.0f deg");
  tooltip("Height above the horizon; negative lights from below.");
  ImGui::SliderFloat("distance", &s.light.distance, 2.0f, 20.0f, "%.1f");
  tooltip("Distance from the object's centre in scene units (the object is 2 units across).\n"
          "Closer: stronger falloff across the object (marble mode); the brightness at the centre stays.");
  ImGui::PopItemWidth();
  ImGui::EndGroup();
  presetButtons("light", lightPresets(), [&](const Placement& p) {
    // The presets' azimuths are relative to the camera: "back" stays behind the object as seen.
    Scene placed = s.scene;
    placed.camera.position = s.camera.position();
    placed.camera.target = s.camera.target;
    placed.light.position = s.light.position();
    placeLight(placed, p.azimuthDeg, p.elevationDeg);
    s.light = Orbit::fromPosition(placed.light.position);
  }, "Where the light stands, as seen from the camera (distance kept): front 30 deg up, side 90 deg to the right,\n"
     "back behind the object (the subsurface glow shows), top straight above. The same as `--light NAME`.");
  ImGui::SameLine();
  if (ImGui::SmallButton("at camera")) s.light = Orbit::fromPosition(s.camera.position());
  tooltip("Light from the viewer's position: flat, shows the pattern best.");
  enumCombo("type", s.scene.light.type, lightTypeChoices(),
            "Point: light from a position, with falloff. Directional: parallel light from that direction (the sun).");
  colour("colour##light", s.scene.light.color, "Colour of the light (linear RGB).");
  ImGui::SliderFloat("intensity", &s.scene.light.intensity, 0.0f, 4.0f, "%.2f");
  tooltip("Brightness of the light: a white surface facing it, as far from it as the object's centre, reflects this much.\n"
          "In the marble mode a point light falls off as 1/d^2 around that distance.");
}

void drawViewSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("View")) return;
  if (ImGui::Button("Frame (F)")) s.requestFrame = true;
  tooltip("Fit the whole object in the view, keeping the viewing direction.");
  ImGui::SameLine();
  if (ImGui::Button("Reset view (Home)")) s.camera = s.initialCamera;
  tooltip("Back to the scene's camera.");
  presetButtons("camera", cameraPresets(), [&](const Placement& p) {
    s.camera.yaw_deg = p.azimuthDeg;
    s.camera.pitch_deg = std::clamp(p.elevationDeg, -89.0f, 89.0f);
  }, "Look from the front (+Z), the side (+X), the back or the top, keeping the distance. The same as `--camera NAME`.");
  ImGui::SliderFloat("field of view", &s.scene.camera.fov_y_deg, 10.0f, 90.0f, "%.0f deg");
  tooltip("Vertical field of view: small is a telephoto (flat), large a wide angle (strong perspective).");
  enumCombo("turntable (T)", s.turntable, {"off", "object", "light"},
            "Slowly turn the object (its model matrix) or the light around the vertical axis.\n"
            "Does not change the scene or the undo history.");
  if (s.turntable != Turntable::Off) {
    ImGui::SliderFloat("speed", &s.turntableDegPerSec, -90.0f, 90.0f, "%.0f deg/s");
    tooltip("Degrees per second; negative turns the other way.");
  }
  float sizeMm = objectSizeMm(s.scene);
  if (ImGui::SliderFloat("object size", &sizeMm, 5.0f, 5000.0f, "%.0f mm", ImGuiSliderFlags_Logarithmic))
    setObjectSizeMm(s.scene, std::clamp(sizeMm, 0.002f, 2e6f));
  tooltip("The object's real size: its largest extent (the scene's mm_per_unit x 2; `--size-mm`).\n"
          "Light travels millimetres in marble: a 5 cm figurine glows through, a 2 m statue is nearly opaque.");
  ImGui::SliderFloat("exposure", &s.scene.render.exposure, -5.0f, 5.0f, "%+.1f EV");
  tooltip("Stops of brightness before tone mapping (+1 doubles the light; `--exposure`). Saved with the scene.");
  colour("background", s.scene.render.background, "Colour behind the object (linear RGB), saved with the scene.");
  enumCombo("antialiasing", s.scene.render.antialias, antialiasChoices(),
            "FXAA smooths the stair-stepped edges of the picture (silhouettes, sharp veins) after tone mapping;\n"
            "flat areas stay exactly as they are. Saved with the scene. Not used by the floor mode.");
  ImGui::Checkbox("vsync", &s.vsync);
  tooltip("Wait for the display's refresh: smooth and cool. Off: measure the real frame time.");
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (F12)")) s.requestScreenshot = true;
  tooltip("Saves the window (panel included) as marble-DATE-TIME.png in the current folder.");
  if (!s.lastScreenshot.empty()) ImGui::TextWrapped("last: %s", s.lastScreenshot.c_str());
}

}  // namespace marble::viewer
