#pragma once
// What the panel and the keys ask for, done by the frame loop between UI and rendering:
// loading meshes, materials and scenes, saving them, framing the object. Every load is
// all-or-nothing: it builds the new thing aside and only then swaps it in, so a bad file
// leaves an error in the panel and the viewer exactly as it was.
#include <string>

#include "marble/render/renderer.h"
#include "viewer_state.h"

namespace marble {

// Loads `source` (a path or builtin:NAME) as the mesh. Throws InputError; the old mesh stays.
void loadMeshInto(Renderer& renderer, ViewerState& s, const std::string& source);

// Hands an already loaded mesh to the renderer and the panel (label, triangles, radius).
void adoptMesh(Renderer& renderer, ViewerState& s, const Mesh& mesh, const std::string& source);

// Hands an already loaded environment map to the renderer and selects it ("map").
void adoptEnvironment(Renderer& renderer, ViewerState& s, const PrefilteredEnvironment& env);

// Puts the whole object in view from the current direction; `aspect` is the 3D view's.
void frameObject(ViewerState& s, float aspect);

// Runs the pending load/save/undo requests; errors go to the panel's status line.
void runFileRequests(Renderer& renderer, ViewerState& s);

// Makes `s` start from `scene`: orbits, the reset targets and an empty undo history.
void adoptScene(ViewerState& s, const Scene& scene);

// "marble-YYYYMMDD-HHMMSS.png" in the current folder, with -2, -3... if taken.
std::string uniqueScreenshotName();

}  // namespace marble
