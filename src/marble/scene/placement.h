#pragma once
// Placing the light and the camera by angles about the object, and the named presets (front,
// side, back, top) that the command line (`--light`, `--camera`) and the viewer's buttons share.
// Pure math on a Scene, no GL.
#include <optional>
#include <string>
#include <vector>

#include "marble/scene/scene.h"

namespace marble {

// Azimuth and elevation in degrees. For the light the azimuth is relative to the camera's (0 =
// from the camera's side of the object, 180 = behind it: back light); for the camera it is
// about +Y, 0 looking from +Z (as the viewer's orbit, orbit.h).
struct Placement {
  const char* name;
  float azimuthDeg, elevationDeg;
};
const std::vector<Placement>& lightPresets();   // front, side, back, top
const std::vector<Placement>& cameraPresets();  // front, side, back, top
std::optional<Placement> findPreset(const std::vector<Placement>& presets, const std::string& name);

// The camera's azimuth about its target, degrees (0 = looking from +Z).
float cameraAzimuthDeg(const Camera& camera);

// Moves the light to the angles about the object (the origin), keeping its distance.
void placeLight(Scene& scene, float azimuthDeg, float elevationDeg);
// Moves the camera to the angles about its target (elevation clamped to +-89 so that the up
// vector stays usable) at `distance`, or at its present distance when `distance` <= 0.
void placeCamera(Scene& scene, float azimuthDeg, float elevationDeg, float distance = 0.0f);

// The object's largest extent in millimetres (the normalized mesh is 2 units across) and back.
inline float objectSizeMm(const Scene& scene) { return 2.0f * scene.mm_per_unit; }
inline void setObjectSizeMm(Scene& scene, float mm) { scene.mm_per_unit = 0.5f * mm; }

}  // namespace marble
