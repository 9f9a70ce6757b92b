#pragma once
// `marble bake INPUT -o DIR [--size N] [--preset P] [--set k=v ...]`: the marble baked onto the
// mesh's texture coordinates (or a fresh unwrap): base_color.png, metallic_roughness.png,
// thickness.png, thickness.exr and material.json (bake/texture_set_files.h; docs/export.md).
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "marble/bake/bake_job.h"
#include "scene_options.h"

namespace marble {

struct BakeCommandOptions {
  SceneOptions scene;  // input, preset, sets, up
  std::filesystem::path outDir;
  int size = 2048;
  int supersample = 2;
  std::string uvFrom = "auto";
  bool progress = false;  // force the progress bar (it shows anyway when stderr is a terminal)
};

// The options bake and export share (input, material, up axis, size, texture coordinates).
void addBakeOptions(CLI::App& cmd, BakeCommandOptions& o);

// The scene and settings from the command line, the bake (bake/bake_job.h) with the progress bar
// on stderr and the texture-coordinate note; shared by `bake` and `export`.
BakeJobResult runBakeFromCommandLine(const BakeCommandOptions& o, BakeOutput kind, const std::filesystem::path& output);

int runBakeCommand(const BakeCommandOptions& o);

}  // namespace marble
