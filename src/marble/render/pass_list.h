#pragma once
// The passes of a frame and what each reads (issue 14): one enumeration, in the order a frame
// runs them, that the renderer's caching (pass_cache.h), its timings, `marble bench`, the
// viewer's performance panel and `marble render --timings` iterate over. A pass declares
// the state it reads (PassInput), the material parameter groups (through the PassBit roles of
// material_params.h) and the passes whose output it reads; the renderer re-runs a cached pass
// exactly when one of those changed since its output was made.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "marble/scene/material_params.h"
#include "marble/scene/scene.h"

namespace marble {

enum class Pass : uint8_t {
  LightDepth,      // the mesh from the light
  Geometry,        // the G-buffer: the mesh from the camera
  Albedo,          // the pattern per pixel (not `marble`: its post pass evaluates it)
  BlurDepth,       // `marble` at half resolution: the depth at the blur's resolution
  Bounce,          // `marble`: the one diffuse bounce, gathered at a quarter of the lighting's texels
  Lighting,        // the mode's picture, or `marble`'s light entering the stone
  SubsurfaceBlur,  // `marble`: diffusion of that light
  Post,            // composition, tone mapping
  Stage,           // `marble` with a backdrop or ground
  Fxaa,            // antialiasing into the target
  Floor,           // `floor`: the whole frame
};
inline constexpr size_t kPassCount = 11;

using PassSet = uint32_t;  // bit 1 << Pass
constexpr PassSet passBit(Pass p) { return 1u << static_cast<unsigned>(p); }

// A value per pass, indexed by Pass.
template <class T>
struct PerPass {
  std::array<T, kPassCount> values{};
  T& operator[](Pass p) { return values[static_cast<size_t>(p)]; }
  const T& operator[](Pass p) const { return values[static_cast<size_t>(p)]; }
  bool operator==(const PerPass&) const = default;
};

// What a pass reads besides the material and other passes' outputs. The first four are the
// renderer's own state (changed by its setters), the rest come with each frame.
enum class PassInput : uint8_t {
  LightMesh,             // the mesh the light's pass draws (setMesh; the proxy) and its maps' size (setLightMapDetail)
  CameraMesh,            // the mesh the camera's passes draw (setMesh; setMeshDetail)
  EnvironmentMap,        // the loaded map (setEnvironmentMap, clearEnvironmentMap)
  TurbulenceGrid,        // the pattern's baked turbulence on or off (setTurbulenceGridEnabled)
  Model,                 // the model matrix
  LightMatrices,         // lightMatrices(scene.light): view-projection, position, direction, range
  CameraMatrices,        // the camera's view-projection (camera and aspect)
  FrameSize,             // width and height the passes draw at (the target's, or less: setResolutionScale)
  Light,                 // scene.light
  Camera,                // scene.camera
  Mode,                  // render.mode
  Environment,           // render.environment, environment_intensity, environment_rotation_deg
  SubsurfaceResolution,  // render.subsurface_resolution
  ObjectSize,            // mm_per_unit
  SeenPattern,           // which program evaluates the pattern: `marble`'s post pass, through the
                         // polish (seenVeinAttenuation, and ior where that is above 0), or the
                         // albedo pass (the surface)
  Scene,                 // anything else of the scene (exposure, background, stage, antialiasing)
};
inline constexpr size_t kPassInputCount = 16;
inline constexpr size_t kRendererStateInputs = 4;  // LightMesh .. TurbulenceGrid

using InputSet = uint32_t;  // bit 1 << PassInput
constexpr InputSet inputBit(PassInput i) { return 1u << static_cast<unsigned>(i); }

struct PassDecl {
  Pass pass;
  const char* name;   // `marble bench` (table and JSON keys), `marble render --timings`
  const char* label;  // the viewer's panel
  const char* what;   // what it makes (the panel's tooltip)
  InputSet inputs;
  uint32_t params;        // PassBit roles (material_params.h): it reads groupsRead(params, mode)
  uint32_t marbleParams;  // roles it takes on in `marble` only
  PassSet reads;          // passes whose output it reads, where they are in the frame (passInFrame)
  // Draws into the frame's picture: runs in every frame that is drawn (Renderer::isCurrent
  // tells when a frame need not be); its inputs are listed for the reader.
  bool everyFrame;
};

std::span<const PassDecl> passList();  // in the order a frame runs them, one per Pass
const PassDecl& passDecl(Pass p);
inline const char* passName(Pass p) { return passDecl(p).name; }

// Whether a frame of `scene` has the pass (it runs there, or is cached).
bool passInFrame(Pass p, const Scene& scene);
// The material groups the pass reads in `mode`.
GroupSet passGroups(Pass p, RenderMode mode);
// The passes whose outputs it reads in a frame of `scene`.
PassSet passReads(Pass p, const Scene& scene);
// One sentence: when the pass re-runs in a frame of `scene` (the panel's tooltip, docs).
std::string passInputsText(Pass p, const Scene& scene);
const char* passInputLabel(PassInput i);

// What `marble`'s post pass keeps for later frames, its diffuse part (blurred light x albedo,
// DiffuseSource::Stored), is made from these passes' outputs.
inline constexpr PassSet kStoredDiffuseReads = passBit(Pass::SubsurfaceBlur) | passBit(Pass::Albedo);

// The passes of the last frame.
struct PassTimes {
  PerPass<double> ms;  // GPU milliseconds (wall clock when serialized) of the pass's last run
  PerPass<bool> ran;   // whether it ran in the last frame (not: cached, or not in that frame)
  // `marble`: where the post pass took the diffuse part from (DiffuseSource: 0 the pattern,
  // evaluated there; 1 the stored albedo; 2 the stored diffuse part); -1 for other modes.
  int diffuseSource = -1;
  // `marble`, the pattern evaluated: what the post pass did with the reflected and the upsampled
  // blurred light (SurfaceReuse: 0 computed, 1 computed and stored, 2 read back); -1 otherwise.
  int surfaceReuse = -1;
};

}  // namespace marble
