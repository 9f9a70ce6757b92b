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
  cmd.add_option("--supersample", o.supersample, "N x N colour samples per texel (1-" + std::to_string(kMaxSupersample) + ", default 2)");
  cmd.add_option("--uv-from", o.uvFrom,
                 "Texture coordinates: auto (the file's if usable, else unwrap; default), file (the file's, or an error), unwrap");
  cmd.add_flag("--progress", o.progress, "Show the progress bar even when stderr is not a terminal");
}

BakeJobResult runBakeFromCommandLine(const BakeCommandOptions& o, BakeOutput kind, const std::filesystem::path& output) {
  // Everything that can be wrong is checked before anything is baked or written.
  const Scene scene = buildScene(o.scene);
  const BakeJob job{.kind = kind, .output = output, .size = o.size, .supersample = o.supersample, .uvSource = parseUvSource(o.uvFrom)};
  checkBakeJob(job);
  const Mesh loaded = loadSceneMesh(scene);
  ProgressBar bar(o.progress || isatty(STDERR_FILENO));
  const BakeJobResult r = runBakeJob(
      scene, loaded, job, [&](double f, const char* stage) { return bar.update(f, stage); },
      [&](const std::string& note) { std::cerr << "note: " << printable(scene.mesh) << ": " << note << "\n"; });
  bar.finish();
  return r;
}

int runBakeCommand(const BakeCommandOptions& o) {
  return reportErrors("bake", [&] {
    const auto start = std::chrono::steady_clock::now();
    const BakeJobResult r = runBakeFromCommandLine(o, BakeOutput::TextureSet, o.outDir);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s: %s, %s, %s (%dx%d), %s (%dx%d, 1.0 = %.3g mm), %s; %s texture coordinates", o.outDir.string().c_str(),
                kMaterialFile, kBaseColorFile, kMetallicRoughnessFile, r.size, r.size, kThicknessFile, r.thicknessSize,
                r.thicknessSize, static_cast<double>(r.thicknessScaleMm), kThicknessExrFile, r.unwrapped ? "unwrapped" : "the file's");
    if (r.unwrapped) std::printf(" (%d charts, %.0f%% of the texture)", r.stats.charts, 100.0 * r.stats.packingEfficiency);
    std::printf("; %.2f s\n", seconds);
    return 0;
  });
}

}  // namespace marble
