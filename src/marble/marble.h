#pragma once
// marble's interface for other programs (`find_package(marble)`, target `marble::marble`;
// docs/embedding.md): load a stone (a mesh and a design), draw it into your own OpenGL
// framebuffer, bake its texture set or export it as glTF. Only the standard library is needed
// to include this header; everything marble uses inside stays behind it.
//
//   marble::api::Stone stone({.input = "statue.obj", .preset = "calacatta"});
//   marble::api::StoneRenderer renderer(stone);      // your GL 4.5 core context is current
//   renderer.render(myFramebuffer, 1280, 720);
//   marble::api::bakeTextureSet(stone, "statue-textures", {.size = 2048});
//
// Errors are exceptions with one line in what(): marble::api::InputError for what the caller
// passed (a file, a value: "statue.obj: line 12: ..."), std::runtime_error for the environment
// (no GL 4.5 context, out of memory).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace marble::api {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What `marble render INPUT --preset P --set k=v --up A` would show.
struct StoneSource {
  std::string input;              // a scene (.json), a mesh (.obj .ply .stl .gltf .glb) or "builtin:NAME"; empty: the showcase scene
  std::string preset;             // a preset name (`marble presets`) or a preset .json; empty: the scene's material
  std::vector<std::string> sets;  // "key=value" overrides, keys as in preset files
  std::string up;                 // the mesh file's up axis: "y" (the default), "z", "x", "-y", "-z", "-x"
};

// A loaded, checked stone: the mesh (normalized to 2 units across), the material, the scene's
// camera, light and picture size. Loading reads every file; nothing later can fail on input.
class Stone {
 public:
  explicit Stone(const StoneSource& source);  // throws InputError
  ~Stone();
  Stone(Stone&&) noexcept;
  Stone& operator=(Stone&&) noexcept;

  std::size_t triangleCount() const;
  int width() const;   // the scene's picture size, in pixels
  int height() const;
  std::string designJson() const;  // the material, as a preset file holds it
  const std::vector<std::string>& warnings() const;  // what loading read past (unknown keys, ...)

  struct Data;
  const Data& data() const { return *data_; }

 private:
  std::unique_ptr<Data> data_;
};

// Draws a stone with marble's renderer. Needs an OpenGL 4.5 core context current on the calling
// thread from construction to destruction (your window's, or an OffscreenContext); marble
// resolves GL through libepoxy, which works with any such context. render() changes GL state
// (programs, bindings, viewport, framebuffer): set yours again afterwards. The stone must outlive
// its renderer.
class StoneRenderer {
 public:
  explicit StoneRenderer(const Stone& stone);  // uploads the mesh and compiles the shaders
  ~StoneRenderer();
  StoneRenderer(const StoneRenderer&) = delete;
  StoneRenderer& operator=(const StoneRenderer&) = delete;

  // Draws the scene into `framebuffer` (0: the default one) over width x height pixels from its
  // origin, replacing what is there (background included). `model` turns the stone: a column-
  // major 4x4 matrix (as glm and OpenGL store it), or null for none. Unchanged frames cost nothing.
  void render(unsigned framebuffer, int width, int height, const float* model = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// An OpenGL 4.5 core context without a window (EGL: Mesa's llvmpipe or a GPU driver), current on
// the constructing thread, for programs that have none: tools, tests, servers. Throws
// std::runtime_error with one line when none can be had.
class OffscreenContext {
 public:
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;
  std::string renderer() const;  // GL_RENDERER

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// `marble bake` and `marble export` (docs/export.md). CPU only: no GL context needed.
struct BakeSettings {
  int size = 2048;              // texels per side, 16-8192 (the thickness map: a quarter, at least 64)
  int supersample = 2;          // N x N colour samples per texel, 1-4
  std::string uvFrom = "auto";  // "auto" (the file's if usable, else an unwrap), "file", "unwrap"
  // Called from the calling thread with the fraction done and the stage; return false to cancel
  // (std::runtime_error "bake cancelled" is thrown and nothing is written). May be empty.
  std::function<bool(double fraction, const char* stage)> progress;
};

struct BakeSummary {
  int size = 0, thicknessSize = 0;
  double thicknessScaleMm = 0;  // what the thickness map's 1.0 stands for
  bool unwrapped = false;       // marble made the texture coordinates
  int charts = 0;               // when unwrapped
  double packingEfficiency = 0; // when unwrapped: the texture's area the triangles cover
  std::string note;             // why "auto" did not keep the file's texture coordinates (empty otherwise)
};

// base_color.png, metallic_roughness.png, thickness.png, thickness.exr and material.json in `folder` (made
// when missing), written together or not at all. Throws InputError before any work for bad
// settings or a folder that cannot be written.
BakeSummary bakeTextureSet(const Stone& stone, const std::filesystem::path& folder, const BakeSettings& settings = {});

// One glTF 2.0 file (.glb, or .gltf with everything inside) with the mesh and the baked set.
BakeSummary exportGltf(const Stone& stone, const std::filesystem::path& file, const BakeSettings& settings = {});

}  // namespace marble::api
