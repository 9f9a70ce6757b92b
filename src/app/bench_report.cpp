#include "bench_report.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "bench_stats.h"

namespace marble {

namespace {

// Microsecond resolution is below the timers' noise; more digits would only be noise too.
double rounded(double ms) { return std::round(ms * 1000.0) / 1000.0; }

double mib(size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

void row(const char* label, const std::vector<double>& values, const std::string& ran = "") {
  const Spread s = spreadOf(values);
  std::printf("%-24s %9.2f %9.2f %9.2f %9.2f  %s\n", label, s.median, s.min, s.max, s.p90, ran.c_str());
}

}  // namespace

void printBenchTable(const BenchResult& r) {
  std::printf("marble bench: %s, %dx%d, mode %s, motion %s, %d frames after %d warm-up\n", r.input.c_str(), r.width,
              r.height, r.mode.c_str(), r.motion.c_str(), r.frames, r.warmup);
  if (r.passTiming == "serial") std::printf("passes serialized (--serial-passes): each timed by the wall clock\n");
  if (!r.turbulenceGrid) std::printf("turbulence evaluated per pixel (--turbulence-grid off)\n");
  std::printf("GL: %s; %s\n", r.glRenderer.c_str(), r.glVersion.c_str());
  std::printf("triangles %zu (%s order), mesh load %.1f ms, upload %.1f ms\n", r.triangles, r.drawOrder.c_str(),
              r.loadMs, r.uploadMs);
  std::printf("light's pass draws %zu triangles (proxy error bound %.5f units); into %dx%d maps: %zu\n",
              r.lightTriangles, r.lightProxyErrorUnits, r.lightMapSize, r.lightMapSize, r.lightMapTriangles);
  if (r.interactionTriangles > 0)
    std::printf("camera's passes draw the interaction copy: %zu triangles (made in %.1f ms)\n",
                r.interactionTriangles, r.interactionMs);
  if (r.resolutionScale < 1.0f)
    std::printf("every pass draws at %.3g of the width and height, stretched to the target (--interaction-resolution)\n",
                r.resolutionScale);
  std::printf("\n");
  std::printf("%-24s %9s %9s %9s %9s  %s\n", "ms", "median", "min", "max", "p90", "ran");
  row("frame (wall)", r.frameMs);
  for (const auto& p : r.passes) {
    const std::string label = "  " + p.name + (r.passTiming == "serial" ? " (wall)" : " (GPU)");
    row(label.c_str(), p.ms, std::to_string(p.runs) + "/" + std::to_string(r.frames));
  }
  if (r.mode == "marble")
    std::printf("  post's diffuse part from: the pattern %d, the stored albedo %d, stored %d (frames)\n",
                r.diffuseSources[0], r.diffuseSources[1], r.diffuseSources[2]);
  row("CPU submit", r.cpuSubmitMs);
  row("CPU all threads", r.cpuProcessMs);
  std::printf("\nrss %.1f MiB (peak %.1f MiB), GL textures and buffers %.1f MiB\n", mib(r.rssBytes),
              mib(r.peakRssBytes), mib(r.glBytes));
}

void printBenchJson(const BenchResult& r) {
  nlohmann::ordered_json j;
  const Spread frame = spreadOf(r.frameMs);
  j["input"] = r.input;
  j["width"] = r.width;
  j["height"] = r.height;
  j["mode"] = r.mode;
  j["motion"] = r.motion;
  j["frames"] = r.frames;
  j["pass_timing"] = r.passTiming;
  j["turbulence_grid"] = r.turbulenceGrid;
  j["warmup"] = r.warmup;
  j["triangles"] = r.triangles;
  j["draw_order"] = r.drawOrder;
  j["light_triangles"] = r.lightTriangles;
  j["light_proxy_error_units"] = r.lightProxyErrorUnits;
  j["interaction_triangles"] = r.interactionTriangles;
  j["interaction_ms"] = rounded(r.interactionMs);
  j["resolution_scale"] = r.resolutionScale;
  j["light_map_size"] = r.lightMapSize;
  j["light_map_triangles"] = r.lightMapTriangles;
  j["light_map_mesh_ms"] = r.lightMapMeshMs;
  j["frame_ms_median"] = rounded(frame.median);
  j["frame_ms_min"] = rounded(frame.min);
  j["frame_ms_max"] = rounded(frame.max);
  j["frame_ms_p90"] = rounded(frame.p90);
  nlohmann::ordered_json passes = nlohmann::ordered_json::object(), whenRun = nlohmann::ordered_json::object(),
                         runs = nlohmann::ordered_json::object();
  for (const auto& p : r.passes) {
    passes[p.name] = rounded(spreadOf(p.ms).median);
    whenRun[p.name] = rounded(spreadOf(p.msWhenRun).median);
    runs[p.name] = p.runs;
  }
  j["passes"] = passes;                  // median over all frames, 0 for a cached frame
  j["passes_when_run_ms"] = whenRun;     // median over the frames in which the pass ran
  j["pass_runs"] = runs;
  if (r.mode == "marble")
    j["post_diffuse_sources"] = {{"pattern", r.diffuseSources[0]}, {"stored_albedo", r.diffuseSources[1]},
                                 {"stored", r.diffuseSources[2]}};
  j["cpu_submit_ms_median"] = rounded(spreadOf(r.cpuSubmitMs).median);
  j["cpu_process_ms_median"] = rounded(spreadOf(r.cpuProcessMs).median);
  j["rss_bytes"] = r.rssBytes;
  j["peak_rss_bytes"] = r.peakRssBytes;
  j["gl_bytes"] = r.glBytes;
  j["load_ms"] = rounded(r.loadMs);
  j["upload_ms"] = rounded(r.uploadMs);
  j["gl_renderer"] = r.glRenderer;
  j["gl_version"] = r.glVersion;
  std::cout << j.dump() << "\n";
}

}  // namespace marble
