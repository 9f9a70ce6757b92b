#pragma once
// The panel's sections, one function each, drawn top to bottom by drawPanel (panel.cpp).
#include "viewer_state.h"

namespace marble::viewer {

void drawTopBar(ViewerState& s);          // preset, render mode, undo/redo (always visible)
void drawFilesSection(ViewerState& s);    // save/load material and scene
void drawMeshSection(ViewerState& s);
// One section per material parameter group (pattern, colour, the paper's model, comparison
// models, scattering, gloss), from the parameters' descriptions.
void drawMaterialSections(ViewerState& s);
void drawLightSection(ViewerState& s);
void drawEnvironmentSection(ViewerState& s);  // studio / none / .hdr map, strength, turn
void drawViewSection(ViewerState& s);     // camera, turntable, background, antialiasing, vsync, screenshot
void drawExportSection(ViewerState& s);   // bake and write glTF or a texture set (export_job.h)
void drawPerformanceSection(ViewerState& s);

// A square pad showing the light's direction from above; click or drag to move it.
void lightPad(const char* id, Orbit& light, const Orbit& camera, float size);

}  // namespace marble::viewer
