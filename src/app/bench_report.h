#pragma once
// What `marble bench` measured, and its two printed forms: a table for people, one JSON
// object for machines (keys listed in docs/performance.md, "Frame benchmark").
#include <cstddef>
#include <array>
#include <string>
#include <vector>

#include "marble/render/pass_list.h"

namespace marble {

struct PassSeries {
  Pass pass;
  std::string name;         // passName(pass): "light_depth", "geometry", ... (render/pass_list.h)
  std::vector<double> ms;   // one per measured frame; 0 when the pass was skipped (cached)
  int runs = 0;             // frames in which the pass actually ran
  std::vector<double> msWhenRun;  // only the frames in which it ran: the cost of one run
};

struct BenchResult {
  std::string input;        // what was benchmarked, as the user named it
  int width = 0, height = 0;
  std::string mode, motion;
  std::string passTiming = "gpu-queries";  // or "serial" (--serial-passes)
  bool turbulenceGrid = true;              // --turbulence-grid
  int frames = 0, warmup = 0;
  size_t triangles = 0;
  std::string drawOrder = "optimized";  // --draw-order
  size_t lightTriangles = 0;            // what the light's pass draws (the proxy's, or all)
  float lightProxyErrorUnits = 0;       // meshoptimizer's bound for the proxy (scene units)
  size_t interactionTriangles = 0;      // --interaction-detail on: what the camera's passes draw
  double interactionMs = 0;             // making that copy
  float resolutionScale = 1.0f;         // --interaction-resolution: the passes' share of width and height
  int lightMapSize = 0;                 // the light's depth map's width (--interaction-light-maps)
  size_t lightMapTriangles = 0;         // what the light's pass draws into maps of that size
  double lightMapMeshMs = 0.0;          // making its copy (reduced maps of a mesh with a proxy)
  double loadMs = 0;        // reading and preparing the mesh (parse, normals, normalization)
  double uploadMs = 0;      // copying it into GL buffers
  std::string glRenderer, glVersion;
  std::vector<double> frameMs;       // wall clock, render call through glFinish
  std::vector<double> cpuSubmitMs;   // CPU of the calling thread while the frame is submitted
  std::vector<double> cpuProcessMs;  // CPU of every thread of the process over the whole frame
  std::vector<PassSeries> passes;
  // `marble`: frames whose post pass took the diffuse part from the pattern (evaluated there),
  // the stored albedo, the stored diffuse part (DiffuseSource).
  std::array<int, 3> diffuseSources{};
  size_t rssBytes = 0, peakRssBytes = 0, glBytes = 0;
};

void printBenchTable(const BenchResult& r);
void printBenchJson(const BenchResult& r);

}  // namespace marble
