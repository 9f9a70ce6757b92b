#include "cmd_bake.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "bake_progress.h"
#include "marble/bake/texture_set_files.h"
#include "marble/core/error.h"

namespace marble {

void addBakeOptions(CLI::App& cmd, BakeCommandOptions& o) {
  cmd.add_option("input", o.scene.input, "Scene (.json) or mesh (.obj .ply .stl .gltf .glb); default: the built-in scene");
  cmd.add_option("--preset", o.scene.preset, "Material preset by name (see `marble presets`) or a preset .json file");
  cmd.add_option("--set", o.scene.sets, "Override one material parameter, key=value (repeatable; keys as in preset files)");
  cmd.add_option("--up", o.scene.up, "Which axis of the mesh file is up: y (default), z, x, -y, -z, -x");
  addAllowOutsideFlag(cmd, o.scene);
  cmd.add_option("--size", o.size, "Texture size in texels, square (" + std::to_string(kMinBakeSize) + "-" +
                                       std::to_string(kMaxBakeSize) + ", default 2048; thickness is a quarter of it)");
  cmd.add_option("--supersample", o.supersample, "N x N colour samples per texel (1-4, default 2)");
  cmd.add_option("--uv-from", o.uvFrom,
                 "Texture coordinates: auto (the file's if usable, else unwrap; default), file (the file's, or an error), unwrap");
  cmd.add_flag("--progress", o.progress, "Show the progress bar even when stderr is not a terminal");
}

int runBakeCommand(const BakeCommandOptions& o) {
  return reportErrors("bake", [&] {
    // Everything that can be wrong is checked before anything is baked or written.
    const Scene scene = buildScene(o.scene);
    if (o.size < kMinBakeSize || o.size > kMaxBakeSize)
      throw InputError("--size", "", "expected a whole number in [" + std::to_string(kMinBakeSize) + ", " +
                                         std::to_string(kMaxBakeSize) + "], got " + std::to_string(o.size));
    if (o.supersample < 1 || o.supersample > 4)
      throw InputError("--supersample", "", "expected 1, 2, 3 or 4, got " + std::to_string(o.supersample));
    const UvSource uvSource = parseUvSource(o.uvFrom);
    checkOutputFolder(o.outDir);
    const auto start = std::chrono::steady_clock::now();
    const Mesh loaded = loadSceneMesh(scene);
    BakeOptions options;
    options.size = o.size;
    options.supersample = o.supersample;
    const BakeMesh mesh = prepareBakeMesh(loaded, uvSource, o.size, options.dilationTexels, scene.mesh);
    if (!mesh.note.empty()) std::cerr << "note: " << scene.mesh << ": " << mesh.note << "\n";
    ProgressBar bar(o.progress || isatty(STDERR_FILENO));
    options.progress = [&](double f, const char* stage) { return bar.update(f, stage); };
    const TextureSet set = bakeTextureSet(mesh.mesh, scene.material, options);
    bar.finish();
    writeTextureSet(o.outDir, set, describeTextureSet(set, scene.material, scene.mm_per_unit, mesh));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s: %s, %s, %s (%dx%d), %s (%dx%d, 1.0 = %.3g mm); %s texture coordinates",
                o.outDir.string().c_str(), kMaterialFile, kBaseColorFile, kMetallicRoughnessFile, set.baseColor.width,
                set.baseColor.height, kThicknessFile, set.thickness.width, set.thickness.height,
                static_cast<double>(set.thicknessScale * scene.mm_per_unit), mesh.unwrapped ? "unwrapped" : "the file's");
    if (mesh.unwrapped) std::printf(" (%d charts, %.0f%% of the texture)", mesh.stats.charts, 100.0 * mesh.stats.packingEfficiency);
    std::printf("; %.2f s\n", seconds);
    return 0;
  });
}

}  // namespace marble
