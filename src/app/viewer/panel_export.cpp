// The panel's Export section: bake the stone onto the mesh and write a .glb/.gltf or a texture
// set folder, on a thread (export_job.h), with progress and cancel.
#include <imgui.h>

#include "panel_sections.h"
#include "panel_widgets.h"

namespace marble::viewer {

void drawExportSection(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Export")) return;
  ExportPanel& e = s.exportPanel;
  ImGui::BeginDisabled(e.running);
  int what = e.textureSet ? 1 : 0;
  ImGui::RadioButton("glTF (.glb / .gltf)", &what, 0);
  tooltip("The mesh, its texture coordinates and the baked textures in one file, with PBR and the volume, "
          "transmission, IOR and specular extensions (docs/export.md).");
  ImGui::SameLine();
  ImGui::RadioButton("texture set (folder)", &what, 1);
  tooltip("base_color.png, metallic_roughness.png, thickness.png and material.json, as `marble bake` writes them.");
  e.textureSet = what == 1;
  static const int kSizes[] = {512, 1024, 2048, 4096};
  if (ImGui::BeginCombo("size", std::to_string(e.size).c_str())) {
    for (int n : kSizes)
      if (ImGui::Selectable(std::to_string(n).c_str(), n == e.size)) e.size = n;
    ImGui::EndCombo();
  }
  tooltip("Texels per side of the base colour; the thickness map is a quarter of it.");
  inputText("path##export", e.path, e.textureSet ? "folder" : "model.glb");
  tooltip("Written atomically, file by file: a bad path or a full disk shows an error and leaves old files as they were.");
  if (ImGui::Button("Export")) e.requestStart = true;
  ImGui::EndDisabled();
  if (e.running) {
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) e.requestCancel = true;
    ImGui::ProgressBar(e.progress, ImVec2(-1, 0), e.stage.c_str());
  }
}

}  // namespace marble::viewer
