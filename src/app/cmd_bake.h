#pragma once
// `marble bake INPUT -o DIR [--size N] [--preset P] [--set k=v ...]`: the marble baked onto the
// mesh's texture coordinates (or a fresh unwrap): base_color.png, metallic_roughness.png,
// thickness.png and material.json (bake/texture_set_files.h; docs/export.md).
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

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

inline constexpr int kMinBakeSize = 16;
inline constexpr int kMaxBakeSize = 8192;

// The options bake and export share (input, material, up axis, size, texture coordinates).
void addBakeOptions(CLI::App& cmd, BakeCommandOptions& o);

int runBakeCommand(const BakeCommandOptions& o);

}  // namespace marble
