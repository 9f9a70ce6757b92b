// marble: a real-time marble renderer. One binary, several commands (see `marble --help`).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "cmd_bake.h"
#include "cmd_bench.h"
#include "cmd_export.h"
#include "cmd_compare.h"
#include "cmd_params.h"
#include "cmd_presets.h"
#include "cmd_render.h"
#include "cmd_texture.h"
#include "marble/core/allocator_tuning.h"
#include "marble/core/message_text.h"
#include "marble/render/mesh_detail.h"
#include "marble/render/renderer.h"
#include "viewer/cmd_view.h"

namespace {

// A setting's value for a help text as a person writes it (0.5, not std::to_string's 0.500000).
std::string helpNumber(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
  return text;
}

int run(int argc, char** argv) {
  using namespace marble;  // before any GL context: llvmpipe frees and re-faults its buffers per frame
  CLI::App app{"marble - real-time marble rendering: procedural veins, subsurface light, Fresnel reflectance.\n"
               "Without an input, every command uses the built-in default scene."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");

  RenderOptions render;
  auto* renderCmd = app.add_subcommand("render", "Render a scene or mesh headless (no display needed) to a PNG");
  addSceneOptions(*renderCmd, render.scene, true);
  renderCmd->add_option("-o,--output", render.output, "Output PNG file, carrying the scene (written atomically; required); with --turntable, a folder");
  renderCmd->add_option("--hdr", render.hdr, "Also write the linear, not tone-mapped image as OpenEXR");
  renderCmd->add_flag("--timings", render.timings, "Print each pass's GPU time");
  renderCmd->add_option("--supersample", render.supersample,
                        "Render N times wider and higher, then average each NxN block in linear light (1-4, default 1)")
      ->check(CLI::Range(1, 4));
  renderCmd->add_option("--quality", render.quality,
                        "draft (default: the scene's settings) or final: supersampled 3x3 (2x2 or less where the size "
                        "limit needs), full-resolution subsurface blur, no FXAA");
  renderCmd->add_option("--turntable", render.turntable,
                        "Render N frames of a full turn into the folder -o names (frame_0000.png, ...)");
  renderCmd->add_option("--turntable-of", render.turntableOf, "What turns: object (default) or light");
  renderCmd->add_option("--video", render.video, "Encode the turntable as .mp4, .webm or animated .webp (needs ffmpeg)");
  renderCmd->add_option("--fps", render.fps, "The video's frames per second (default 24)");

  ViewOptions view;
  auto* viewCmd = app.add_subcommand("view", "Open the interactive viewer (needs a display)");
  addSceneOptions(*viewCmd, view.scene, true);
  viewCmd->add_option("--frames", view.frames, "Draw this many frames, then exit (0 = run until closed)")->check(CLI::Range(0, 1000000000));
  viewCmd->add_option("--screenshot", view.screenshot, "After the last frame, save the whole window (panel included) as PNG");
  viewCmd->add_flag("--dev", view.dev, "Development mode: shaders hot-reload (R) from $MARBLE_SHADER_DIR, else the source tree's shaders/");
  viewCmd->add_option("--turntable", view.turntable, "Start turning: off (default), object or light (the panel's turntable)");
  viewCmd->add_option("--interaction-detail", view.interactionDetail,
                      "While the camera or object moves, draw a simplified mesh (at most about " +
                          std::to_string(kInteractionTriangles) +
                          " triangles) and the full mesh on the first still frame: auto (default: on above " +
                          std::to_string(kInteractionMinTriangles) + " triangles), on, off");
  viewCmd->add_option("--interaction-resolution", view.interactionResolution,
                      "While the camera, object or light moves, draw every pass at this fraction of the view's width "
                      "and height, stretched to the view, and at the full resolution on the first still frame "
                      "(default " + helpNumber(kDefaultInteractionResolution) + "; 1: off; at least " +
                          helpNumber(Renderer::kMinResolutionScale) + ")");
  viewCmd->add_option("--interaction-light-maps", view.interactionLightMaps,
                      "While the object or light moves, draw the light's maps at the --interaction-resolution share "
                      "of their size (512x512 of 1024x1024 at 0.5), and at the full size on the first still frame: "
                      "on (default), off")
      ->check(CLI::IsMember({"on", "off"}));
  viewCmd->add_option("--turntable-speed", view.turntableSpeed, "Turntable speed in degrees per second (default 15; negative turns the other way)");

  TextureOptions texture;
  auto* textureCmd = app.add_subcommand("texture", "Write the marble pattern's stages as PNGs (the paper's Figures 3 and 4)");
  textureCmd->add_option("-o,--output", texture.out_dir, "Output folder")->required();
  textureCmd->add_option("--size", texture.size, "Image size in pixels (square)")->check(CLI::Range(8, 8192));
  textureCmd->add_option("--preset", texture.preset, "Material preset");
  textureCmd->add_option("--set", texture.sets, "Override one material parameter, key=value (repeatable)");
  textureCmd->add_option("--slice", texture.slice,
                         "Vein models: marble.png is the solid pattern on the plane AXIS=OFFSET (x, y or z; default z=0)");
  textureCmd->add_flag("--tile", texture.tile, "Write a tile that repeats without a seam");

  BakeCommandOptions bake;
  auto* bakeCmd = app.add_subcommand("bake", "Bake the marble onto the mesh's texture coordinates (or an automatic unwrap): "
                                              "base colour, metallic-roughness and thickness PNGs, thickness.exr (mm) and material.json");
  addBakeOptions(*bakeCmd, bake);
  bakeCmd->add_option("-o,--output", bake.outDir, "Output folder (created if needed)")->required();

  ExportCommandOptions exportOpts;
  auto* exportCmd = app.add_subcommand("export", "Bake the marble and write the mesh with its textures as glTF 2.0 (.glb or .gltf), "
                                                  "PBR metallic-roughness with KHR_materials_volume, _diffuse_transmission, _ior, _specular");
  addBakeOptions(*exportCmd, exportOpts.bake);
  exportCmd->add_option("-o,--output", exportOpts.output, "Output file, model.glb (binary) or model.gltf (one JSON file)")->required();

  app.add_subcommand("presets", "List the built-in material presets");

  std::string paramsDoc;
  auto* paramsCmd = app.add_subcommand("params", "List every material parameter: range, unit, default, the modes that read it");
  paramsCmd->add_option("--update-doc", paramsDoc, "Rewrite the parameter tables of this Markdown file (docs/materials.md)");

  BenchOptions bench;
  auto* benchCmd = app.add_subcommand("bench", "Measure frame and pass times and memory while the camera, light or material changes");
  addBenchOptions(*benchCmd, bench);

  CompareOptions compare;
  auto* compareCmd = app.add_subcommand("compare", "Compare a render with a reference EXR: silhouette IoU, exposure scale, relative RMSE, SSIM");
  compareCmd->add_option("reference", compare.reference, "Reference EXR (e.g. from tools/cycles_reference.py)")->required();
  compareCmd->add_option("test", compare.test, "EXR to judge (e.g. marble render --hdr)")->required();
  compareCmd->add_flag("--json", compare.json, "Print one JSON object");
  compareCmd->add_option("--downsample", compare.downsample,
                         "Box-filter both images by this whole factor before comparing (docs/quality.md compares at 4)")
      ->check(CLI::Range(1, 64));
  compareCmd->add_option("--side-by-side", compare.sideBySide,
                         "Write a PNG: reference | test at the best-fit exposure, both through the display transform");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Bad usage: one line, exit code 2, like bad input.
    std::cerr << "marble: " << e.what() << " (see marble --help)\n";
    return 2;
  }

  if (renderCmd->parsed()) return runRenderCommand(render);
  if (viewCmd->parsed()) return runViewCommand(view);
  if (textureCmd->parsed()) return runTextureCommand(texture);
  if (bakeCmd->parsed()) return runBakeCommand(bake);
  if (exportCmd->parsed()) return runExportCommand(exportOpts);
  if (app.got_subcommand("presets")) return runPresetsCommand();
  if (paramsCmd->parsed()) return runParamsCommand(paramsDoc);
  if (benchCmd->parsed()) return runBenchCommand(bench);
  if (compareCmd->parsed()) return runCompareCommand(compare);
  return 2;
}

}  // namespace

// Each command reports its own errors (reportErrors: one line, exit 2 for bad input, 1 for the
// environment); this is the last net, so that no exception ever ends marble with an abort and a
// core dump: running out of memory while parsing arguments or outside a command's net is one
// line and exit 1 as well.
int main(int argc, char** argv) {
  try {
    marble::keepFreedMemoryForReuse();  // before any GL context: llvmpipe frees and re-faults its buffers per frame
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("marble: out of memory\n", stderr);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "marble: %s\n", marble::printable(e.what(), marble::kMessageLineLimit).c_str());
  } catch (...) {
    std::fputs("marble: unexpected internal error (an exception of unknown type)\n", stderr);
  }
  return 1;
}
