#pragma once
// Everything the viewer shows and edits, apart from GL: the scene, orbit controls, what
// the panel reports, and requests from the panel to the frame loop (which owns GL and does
// the work, so the panel never touches the renderer).
#include <deque>
#include <map>
#include <string>

#include "interaction_detail.h"
#include "marble/render/renderer.h"
#include "marble/scene/orbit.h"
#include "marble/scene/scene.h"
#include "marble/scene/undo_stack.h"

namespace marble {

enum class Turntable { Off, Object, Light };

// The Export section's settings and the job's progress (export_job.h does the work).
struct ExportPanel {
  std::string path = "marble.glb";
  int size = 1024;
  bool textureSet = false;      // a folder of PNGs + material.json instead of a glTF file
  bool requestStart = false, requestCancel = false;
  bool running = false;
  float progress = 0.0f;
  std::string stage;
};

struct ViewerState {
  Scene scene;
  Orbit camera;
  Orbit light;
  Orbit initialCamera;            // "reset view" goes back here
  Light initialLight;             // the light section's reset
  Orbit initialLightOrbit;
  float meshRadius = 1.7320508f;  // bounding sphere about the origin, for framing (F)
  std::string meshLabel;          // what is loaded, for the panel
  size_t triangles = 0;
  // Each mesh file's up axis, as the scene, --up or the panel said it: a file loaded again
  // gets its own back; a new file starts at +Y (the OBJ/glTF convention), never a guess.
  std::map<std::string, UpAxis> meshUp;

  // Path boxes.
  std::string meshPathInput;
  std::string materialPathInput = "my-marble.json";
  std::string scenePathInput = "scene.json";
  std::string environmentPathInput;

  std::string loadedEnvironment;  // the .hdr the renderer holds ("" = none); scene.render.environment_map may differ
  std::string environmentLabel;   // its size and load time, for the panel

  std::string presetName;         // the preset the material started from
  Material presetMaterial;        // what "reset" returns a section to
  UndoStack undo;

  ExportPanel exportPanel;

  std::string status;             // last message (errors in red)
  bool statusIsError = false;
  std::string lastScreenshot;     // absolute path of the last screenshot saved

  std::deque<float> frameMs;      // recent frame times for the graph
  PassTimes passTimes;

  Turntable turntable = Turntable::Off;
  float turntableDegPerSec = 15.0f;
  float turntableAngle = 0.0f;    // degrees; transient, not part of the scene or undo

  bool vsync = true;
  InteractionDetailSetting interactionDetail = InteractionDetailSetting::Auto;  // the Performance section
  float interactionResolution = kDefaultInteractionResolution;                 // the same; 1: off
  bool interactionLightMaps = true;  // the same: the light's maps at that resolution while the object or light moves
  bool showPanel = true;
  bool showHelp = false;
  bool devMode = false;
  float panelWidth = 0.0f;        // in window coordinates, 0 when hidden; the 3D view is right of it
  float contentScale = 1.0f;      // HiDPI: the monitor's content scale, applied to the UI
  bool contentScaleChanged = false;

  // Requests from the panel/keys to the frame loop.
  bool requestMeshLoad = false;
  bool requestScreenshot = false;
  bool requestShaderReload = false;
  bool requestFrame = false;
  bool requestUndo = false, requestRedo = false;
  bool requestSaveMaterial = false, requestLoadMaterial = false;
  bool requestSaveScene = false, requestLoadScene = false;
  bool requestEnvironmentLoad = false;  // loads environmentPathInput

  void setError(const std::string& message) { status = message; statusIsError = true; }
  void setStatus(const std::string& message) { status = message; statusIsError = false; }
};

// The undoable part of the state, and putting one back.
EditState currentEdit(const ViewerState& s);
void applyEdit(ViewerState& s, const EditState& e);

// Draws the ImGui panel (docked at the left, full height); edits `state` in place.
void drawPanel(ViewerState& state);
void drawHelpOverlay(ViewerState& state);

}  // namespace marble
