#pragma once
// What changes between the frames of `marble bench`, as in a user's session: the camera
// orbits, the light turns, both, or one lighting-only material parameter moves. Each kind
// exercises a different set of the renderer's cached passes.
#include <string>

#include "marble/scene/scene.h"

namespace marble {

// params: the gloss (k_schlick, roughness) -- the post pass re-shades;
// scattering: sigma_s_mm -- the lighting and the subsurface blur re-run;
// pattern: what bends the veins of the material's model (turb_power for the paper's, vein_warp
// for network and breccia) -- the pass that evaluates the pattern re-runs.
enum class BenchMotion { None, Camera, Light, Both, Params, Scattering, Pattern };

// "none", "camera", "light", "both", "params"; throws InputError naming --motion otherwise.
BenchMotion parseBenchMotion(const std::string& name);
const char* benchMotionName(BenchMotion motion);

// The scene of frame `frame` (0 = `base` itself). Computed from the frame number rather than
// accumulated, so warm-up and measured frames follow one continuous path.
Scene sceneAtFrame(const Scene& base, BenchMotion motion, int frame);

}  // namespace marble
