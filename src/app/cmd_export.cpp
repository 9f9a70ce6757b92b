#include "cmd_export.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "bake_progress.h"
#include "marble/bake/bake_mesh.h"
#include "marble/bake/texture_set_files.h"
#include "marble/bake/gltf_export.h"
#include "marble/core/error.h"

namespace marble {

int runExportCommand(const ExportCommandOptions& o) {
  return reportErrors("export", [&] {
    const BakeCommandOptions& b = o.bake;
    const Scene scene = buildScene(b.scene);
    if (o.output.empty()) throw InputError("-o", "", "an output file is required (e.g. -o model.glb)");
    gltfContainerFor(o.output);  // .glb or .gltf, before any work
    if (b.size < kMinBakeSize || b.size > kMaxBakeSize)
      throw InputError("--size", "", "expected a whole number in [" + std::to_string(kMinBakeSize) + ", " +
                                         std::to_string(kMaxBakeSize) + "], got " + std::to_string(b.size));
    if (b.supersample < 1 || b.supersample > 4)
      throw InputError("--supersample", "", "expected 1, 2, 3 or 4, got " + std::to_string(b.supersample));
    const UvSource uvSource = parseUvSource(b.uvFrom);
    // An unwritable place fails here, before the bake; the folder must exist already.
    const auto folder = o.output.has_parent_path() ? o.output.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) throw InputError(o.output.string(), "", "the folder " + folder.string() + " does not exist");
    if (::access(folder.c_str(), W_OK) != 0) throw InputError(o.output.string(), "", "the folder " + folder.string() + " is not writable");
    const auto start = std::chrono::steady_clock::now();
    const Mesh loaded = loadSceneMesh(scene);
    BakeOptions options;
    options.size = b.size;
    options.supersample = b.supersample;
    const BakeMesh mesh = prepareBakeMesh(loaded, uvSource, b.size, options.dilationTexels, scene.mesh);
    if (!mesh.note.empty()) std::cerr << "note: " << scene.mesh << ": " << mesh.note << "\n";
    ProgressBar bar(b.progress || isatty(STDERR_FILENO));
    options.progress = [&](double f, const char* stage) { return bar.update(f, stage); };
    const TextureSet set = bakeTextureSet(mesh.mesh, scene.material, options);
    bar.finish();
    writeGltf(o.output, {mesh.mesh, set, scene.material, scene.mm_per_unit});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s (%zu triangles, %dx%d textures, %s texture coordinates; %.2f s)\n", o.output.string().c_str(),
                mesh.mesh.triangleCount(), set.baseColor.width, set.baseColor.height, mesh.unwrapped ? "unwrapped" : "the file's",
                seconds);
    return 0;
  });
}

}  // namespace marble
