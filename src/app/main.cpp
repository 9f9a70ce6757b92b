// marble: a real-time marble renderer. One binary, several commands (see `marble --help`).
#include <CLI/CLI.hpp>

#include <iostream>

#include "cmd_bench.h"
#include "cmd_compare.h"
#include "cmd_presets.h"
#include "cmd_render.h"
#include "cmd_texture.h"
#include "marble/core/allocator_tuning.h"
#include "viewer/cmd_view.h"

int main(int argc, char** argv) {
  using namespace marble;
  keepFreedMemoryForReuse();  // before any GL context: llvmpipe frees and re-faults its buffers per frame
  CLI::App app{"marble - real-time marble rendering: procedural veins, subsurface light, Fresnel reflectance.\n"
               "Without an input, every command uses the built-in default scene."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");

  RenderOptions render;
  auto* renderCmd = app.add_subcommand("render", "Render a scene or mesh headless (no display needed) to a PNG");
  addSceneOptions(*renderCmd, render.scene, true);
  renderCmd->add_option("-o,--output", render.output, "Output PNG file (written atomically; required)");
  renderCmd->add_option("--hdr", render.hdr, "Also write the linear, not tone-mapped image as OpenEXR");
  renderCmd->add_flag("--timings", render.timings, "Print each pass's GPU time");
  renderCmd->add_option("--supersample", render.supersample,
                        "Render N times wider and higher, then average each NxN block in linear light (1-4, default 1)")
      ->check(CLI::Range(1, 4));

  ViewOptions view;
  auto* viewCmd = app.add_subcommand("view", "Open the interactive viewer (needs a display)");
  addSceneOptions(*viewCmd, view.scene, true);
  viewCmd->add_option("--frames", view.frames, "Draw this many frames, then exit (0 = run until closed)")->check(CLI::Range(0, 1000000000));
  viewCmd->add_option("--screenshot", view.screenshot, "After the last frame, save the whole window (panel included) as PNG");
  viewCmd->add_flag("--dev", view.dev, "Development mode: shaders hot-reload (R) from $MARBLE_SHADER_DIR, else the source tree's shaders/");
  viewCmd->add_option("--turntable", view.turntable, "Start turning: off (default), object or light (the panel's turntable)");
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

  app.add_subcommand("presets", "List the built-in material presets");

  BenchOptions bench;
  auto* benchCmd = app.add_subcommand("bench", "Measure frame and pass times and memory while the camera, light or material changes");
  addBenchOptions(*benchCmd, bench);

  CompareOptions compare;
  auto* compareCmd = app.add_subcommand("compare", "Compare a render with a reference EXR: silhouette IoU, exposure scale, relative RMSE, SSIM");
  compareCmd->add_option("reference", compare.reference, "Reference EXR (e.g. from tools/cycles_reference.py)")->required();
  compareCmd->add_option("test", compare.test, "EXR to judge (e.g. marble render --hdr)")->required();
  compareCmd->add_flag("--json", compare.json, "Print one JSON object");

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
  if (app.got_subcommand("presets")) return runPresetsCommand();
  if (benchCmd->parsed()) return runBenchCommand(bench);
  if (compareCmd->parsed()) return runCompareCommand(compare);
  return 2;
}
