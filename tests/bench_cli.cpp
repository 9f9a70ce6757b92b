// `marble bench` end to end: it runs, its JSON carries the documented keys, the motions
// exercise the passes they should, and bad input is one line with exit code 2.
// Nothing here asserts a time: only that times are measured and consistent.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>

#include "cli_support.h"
#include "marble/core/image.h"

using namespace marble::test;

namespace {

const std::string kSmall = "bench --frames 3 --warmup 1 --width 64 --height 64";

// The JSON object is the one line of stdout that starts with '{' (stderr is merged in).
nlohmann::json benchJson(const std::string& extra) {
  const auto r = runMarble(kSmall + " --json " + extra);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line.front() == '{') return nlohmann::json::parse(line);
  ADD_FAILURE() << "no JSON object in: " << r.output;
  return nlohmann::json::object();
}

size_t countLines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace

TEST(CliBench, JsonHasTheDocumentedKeys) {
  const auto j = benchJson("");
  for (const char* key : {"frame_ms_median", "frame_ms_min", "frame_ms_max", "passes", "rss_bytes", "gl_bytes",
                          "triangles", "width", "height", "mode", "motion", "load_ms"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j.value("width", 0), 64);
  EXPECT_EQ(j.value("height", 0), 64);
  EXPECT_EQ(j.value("mode", ""), "marble");
  EXPECT_EQ(j.value("motion", ""), "none");
  EXPECT_EQ(j.value("frames", 0), 3);
  EXPECT_GT(j.value("triangles", 0), 0);
  EXPECT_GT(j.value("rss_bytes", 0.0), 0.0);
  EXPECT_GT(j.value("gl_bytes", 0.0), 64.0 * 64.0 * 8.0) << "at least the G-buffer's colour planes";
  EXPECT_GT(j.value("frame_ms_min", 0.0), 0.0);
  EXPECT_LE(j.value("frame_ms_min", 0.0), j.value("frame_ms_median", 0.0));
  EXPECT_LE(j.value("frame_ms_median", 0.0), j.value("frame_ms_max", 0.0));
  ASSERT_TRUE(j["passes"].is_object());
  for (const char* pass : {"light_depth", "geometry", "lighting", "post", "fxaa"}) {
    ASSERT_TRUE(j["passes"].contains(pass)) << pass;
    EXPECT_GE(j["passes"][pass].get<double>(), 0.0) << pass;
  }
}

// Each motion re-runs exactly the passes whose inputs it changes (the warm-up frame pays
// for the first full frame, so "none" measures only cached frames).
TEST(CliBench, MotionsRunThePassesTheyChange) {
  struct Case {
    const char* motion;
    int lightDepth, geometry, pattern, lighting, blurDepth, storedDiffuse, bounce;
  };
  // `marble` evaluates the pattern in the post pass (no albedo pass), and reuses the stored
  // diffuse part when neither the light nor the albedo changed. The bounce follows the view and
  // the light, and of the material the base colour and the ior (scattering: its last draw alone,
  // which applies them; BouncePass::run).
  for (const Case& c : {Case{"none", 0, 0, 0, 0, 0, 0, 0}, Case{"camera", 0, 3, 3, 3, 3, 0, 3},
                        Case{"light", 3, 0, 0, 3, 0, 0, 3}, Case{"both", 3, 3, 3, 3, 3, 0, 3},
                        Case{"params", 0, 0, 0, 0, 0, 3, 0}, Case{"scattering", 0, 0, 0, 3, 0, 0, 3},
                        Case{"pattern", 0, 0, 3, 0, 0, 0, 0}}) {
    const auto j = benchJson(std::string("--motion ") + c.motion);
    ASSERT_TRUE(j.contains("pass_runs")) << c.motion;
    EXPECT_EQ(j.value("motion", ""), c.motion);
    EXPECT_EQ(j["pass_runs"].value("light_depth", -1), c.lightDepth) << c.motion;
    EXPECT_EQ(j["pass_runs"].value("geometry", -1), c.geometry) << c.motion;
    EXPECT_FALSE(j["pass_runs"].contains("albedo")) << c.motion;
    EXPECT_EQ(j["post_diffuse_sources"].value("pattern", -1), c.pattern) << c.motion;
    EXPECT_EQ(j["post_diffuse_sources"].value("stored", -1), c.storedDiffuse) << c.motion;
    EXPECT_EQ(j["pass_runs"].value("lighting", -1), c.lighting) << c.motion;
    EXPECT_EQ(j["pass_runs"].value("blur_depth", -1), c.blurDepth) << c.motion << ": the blur's depth follows the view only";
    EXPECT_EQ(j["pass_runs"].value("bounce", -1), c.bounce) << c.motion;
    EXPECT_EQ(j["pass_runs"].value("post", -1), std::string(c.motion) == "none" ? 0 : 3)
        << c.motion << ": an unchanged frame draws nothing";
    if (c.geometry == 0) {
      EXPECT_EQ(j["passes"].value("geometry", -1.0), 0.0) << "a cached pass costs nothing";
    }
  }
}

TEST(CliBench, SerialPassesAreTimedByTheWallClock) {
  const auto j = benchJson("--motion camera --serial-passes");
  EXPECT_EQ(j.value("pass_timing", ""), "serial");
  for (const char* pass : {"geometry", "blur_depth", "lighting", "subsurface_blur", "post", "fxaa"})
    EXPECT_GT(j["passes"].value(pass, 0.0), 0.0) << pass << " runs every frame of an orbit";
  EXPECT_EQ(benchJson("").value("pass_timing", ""), "gpu-queries");
  EXPECT_FALSE(benchJson("--subsurface-resolution full")["passes"].contains("blur_depth"))
      << "at full resolution the G-buffer's depth serves";
}

TEST(CliBench, TurbulenceGridCanBeTurnedOffToCompare) {
  const auto on = benchJson("--motion pattern");
  const auto off = benchJson("--motion pattern --turbulence-grid off");
  EXPECT_TRUE(on.value("turbulence_grid", false));
  EXPECT_FALSE(off.value("turbulence_grid", true));
  // The grid is GL memory the renderer holds (256^3 x 2 bytes for the default solid marble).
  EXPECT_GE(on.value("gl_bytes", 0.0) - off.value("gl_bytes", 0.0), 256.0 * 256 * 256 * 2);
}

// The default mesh (25,600 triangles) is below the light proxy's and the interaction copy's
// thresholds (render/mesh_detail.h): both draw the whole mesh. (The copies themselves are
// tested in tests/mesh_detail_gl_test.cpp.)
TEST(CliBench, MeshDetailOptionsAreReported) {
  const auto plain = benchJson("--motion camera");
  EXPECT_EQ(plain.value("draw_order", ""), "optimized");
  EXPECT_EQ(plain.value("light_triangles", 0), plain.value("triangles", 1));
  EXPECT_EQ(plain.value("light_proxy_error_units", 1.0), 0.0);
  EXPECT_EQ(plain.value("interaction_triangles", 1), 0) << "not made unless asked for";
  EXPECT_EQ(benchJson("--draw-order file").value("draw_order", ""), "file");
  const auto interaction = benchJson("--motion camera --interaction-detail on --light-proxy off");
  EXPECT_EQ(interaction.value("interaction_triangles", 0), interaction.value("triangles", 1));
  EXPECT_EQ(interaction["pass_runs"].value("geometry", 0), 3);
}

// Dynamic resolution: reported, and the passes still run every camera frame.
TEST(CliBench, InteractionResolutionIsReported) {
  EXPECT_EQ(benchJson("").value("resolution_scale", 0.0), 1.0);
  const auto half = benchJson("--motion camera --interaction-resolution 0.5");
  EXPECT_EQ(half.value("resolution_scale", 0.0), 0.5);
  EXPECT_EQ(half["pass_runs"].value("geometry", 0), 3);
  EXPECT_EQ(half.value("width", 0), 64) << "the target keeps its size";
}

// The light's maps at interaction detail: their size is reported and follows the resolution
// scale only when asked for; --screenshot saves the last frame at the target's size.
TEST(CliBench, InteractionLightMapsAreReportedAndTheLastFrameSaved) {
  EXPECT_EQ(benchJson("--interaction-resolution 0.5").value("light_map_size", 0), 1024);
  const auto reduced = benchJson("--motion light --interaction-resolution 0.5 --interaction-light-maps on");
  EXPECT_EQ(reduced.value("light_map_size", 0), 512);
  EXPECT_EQ(reduced["pass_runs"].value("light_depth", 0), 3);
  const auto dir = tempDir("bench-shot");
  const auto shot = dir / "last.png";
  ASSERT_EQ(runMarble(kSmall + " --screenshot " + shot.string()).exitCode, 0);
  const marble::ImageRGBA8 img = marble::readPng(shot);
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 64);
}

TEST(CliBench, OtherModesHaveAnAlbedoPass) {
  const auto j = benchJson("--mode paper --motion pattern");
  EXPECT_EQ(j["pass_runs"].value("albedo", -1), 3);
  EXPECT_FALSE(j.contains("post_diffuse_sources"));
}

TEST(CliBench, FloorModeTimesTheFloorPass) {
  const auto j = benchJson("--mode floor --motion camera");
  EXPECT_EQ(j.value("mode", ""), "floor");
  ASSERT_TRUE(j.contains("passes"));
  EXPECT_TRUE(j["passes"].contains("floor"));
  EXPECT_FALSE(j["passes"].contains("geometry"));
}

TEST(CliBench, FxaaIsAPassOnlyWhenAntialiasingIsOn) {
  const auto on = benchJson("--motion params");
  EXPECT_EQ(on["pass_runs"].value("fxaa", -1), 3) << "FXAA runs every frame that changed";
  const auto off = benchJson("--antialias none");
  EXPECT_FALSE(off["passes"].contains("fxaa"));
  EXPECT_TRUE(off["passes"].contains("post"));
}

TEST(CliBench, TablePrintsSpreadPassesAndMemory) {
  const auto r = runMarble(kSmall + " --motion camera");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* word : {"median", "min", "max", "p90", "frame", "light_depth", "geometry", "lighting", "CPU",
                           "rss", "triangles", "64x64", "motion camera"})
    EXPECT_NE(r.output.find(word), std::string::npos) << word << " in:\n" << r.output;
}

TEST(CliBench, BadInputIsOneLineAndExitTwo) {
  for (const std::string& args : {kSmall + " --motion wobble", std::string("bench --width 64 --height 64 --frames 0"), std::string("bench --width 64 --height 64 --warmup -1"),
                                 kSmall + " --mode sparkly", kSmall + " /nonexistent/mesh.obj",
                                 kSmall + " --turbulence-grid maybe", kSmall + " --interaction-resolution 0.1",
                                 kSmall + " --interaction-light-maps half"}) {
    const auto r = runMarble(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_EQ(countLines(r.output), 1u) << args << "\n" << r.output;
  }
  EXPECT_NE(runMarble(kSmall + " --motion wobble").output.find("--motion"), std::string::npos);
}
