#pragma once
// `marble export INPUT -o model.glb|model.gltf [bake options]`: the mesh, its texture coordinates
// and the baked texture set as one glTF 2.0 file (bake/gltf_export.h; docs/export.md).
#include "cmd_bake.h"

namespace marble {

struct ExportCommandOptions {
  BakeCommandOptions bake;  // bake.outDir unused
  std::filesystem::path output;
};

int runExportCommand(const ExportCommandOptions& o);

}  // namespace marble
