#include "cmd_export.h"

#include <chrono>
#include <cstdio>

#include "marble/core/error.h"

namespace marble {

int runExportCommand(const ExportCommandOptions& o) {
  return reportErrors("export", [&] {
    const auto start = std::chrono::steady_clock::now();
    const BakeJobResult r = runBakeFromCommandLine(o.bake, BakeOutput::Gltf, o.output);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s (%zu triangles, %dx%d textures, %s texture coordinates; %.2f s)\n", o.output.string().c_str(),
                r.triangles, r.size, r.size, r.unwrapped ? "unwrapped" : "the file's", seconds);
    return 0;
  });
}

}  // namespace marble
