#pragma once
// One bake as every front end runs it -- `marble bake`, `marble export`, the viewer's Export
// section (background_export.h) and the public interface (marble/marble.h): the settings and the
// output are checked before any work, then the scene's mesh is given texture coordinates
// (bake_mesh.h), baked (texture_bake.h) and written, a texture-set folder or a glTF file, each file
// atomically. One place for the limits, the checks and the order, so the four cannot drift apart.
#include <filesystem>
#include <functional>
#include <string>

#include "marble/bake/bake_mesh.h"
#include "marble/bake/texture_bake.h"
#include "marble/scene/scene.h"

namespace marble {

inline constexpr int kMinBakeSize = 16;
inline constexpr int kMaxBakeSize = 8192;
inline constexpr int kMaxSupersample = 4;

enum class BakeOutput { TextureSet, Gltf };  // a folder (bake/texture_set_files.h), or .glb/.gltf (bake/gltf_export.h)

struct BakeJob {
  BakeOutput kind = BakeOutput::TextureSet;
  std::filesystem::path output;  // the folder, or the .glb/.gltf file
  int size = 2048;               // kMinBakeSize..kMaxBakeSize
  int supersample = 2;           // 1..kMaxSupersample
  UvSource uvSource = UvSource::Auto;
};

// What was baked, for the front ends' one-line summaries.
struct BakeJobResult {
  size_t triangles = 0;
  int size = 0, thicknessSize = 0;
  float thicknessScaleMm = 0;  // the thickness map's 1.0
  bool unwrapped = false;
  UvUnwrapStats stats;         // when unwrapped
  std::string note;            // why `auto` did not keep the file's texture coordinates (empty otherwise)
};

// Throws InputError (named after the command line's options) for settings out of range or an
// output that cannot be written; creates nothing.
void checkBakeJob(const BakeJob& job);

// checkBakeJob, then the whole bake of `loaded` (the scene's mesh, loadSceneMesh). `progress` as BakeOptions::progress (may be empty; returning
// false cancels: BakeCancelled, nothing written). `note` (may be empty) hears, before the bake
// starts, why the file's texture coordinates were not kept.
BakeJobResult runBakeJob(const Scene& scene, const Mesh& loaded, const BakeJob& job, const std::function<bool(double, const char*)>& progress = {},
                         const std::function<void(const std::string&)>& note = {});

}  // namespace marble
