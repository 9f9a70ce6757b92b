// marble_load_phases: loadMesh's steps timed one by one (issue 20, "loading at disk speed"): the
// file read, the parse, up axis and normalization, the points (equal positions), duplicate
// triangles, the crease normals, and the whole loadMesh for comparison. Medians over interleaved runs of wall time, of the
// process's CPU time (all threads) and of the calling thread's CPU time (the critical path: about
// the wall time on free cores): on a shared machine the CPU times are the steadier figures. A mesh
// without file normals has its duplicates dropped by the normals' pass (vertex_normals.h): its
// "duplicates" column is then empty and "normals" holds both.
//
//   marble_load_phases [--runs N] [--up z] [--crease DEG] FILE...      (.obj .ply .stl)
//
// Before the timed runs, the steps run in a row are checked to give loadMesh's mesh bit for bit
// (so the table times what loadMesh does; loadMesh's own checks of the parsed mesh are left out).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "marble/core/allocator_tuning.h"
#include "marble/core/input_file.h"
#include "marble/mesh/duplicate_triangles.h"
#include "marble/mesh/mesh.h"
#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/point_ids.h"
#include "marble/mesh/vertex_normals.h"

#include "load_timing.h"

namespace {

using load_timing::cpuMs;
using load_timing::median;
using load_timing::threadMs;
using load_timing::wallMs;

bool sameMesh(const marble::Mesh& a, const marble::Mesh& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.positions, b.positions) && same(a.normals, b.normals) && same(a.texcoords, b.texcoords) &&
         same(a.indices, b.indices);
}

constexpr const char* kPhases[] = {"read", "parse", "up + normalize", "points", "duplicates", "normals", "sum", "loadMesh"};
constexpr size_t kPhaseCount = std::size(kPhases);

// One load, step by step; adds each step's wall and CPU time.
marble::Mesh loadInSteps(const std::filesystem::path& path, marble::UpAxis up, float crease,
                         std::vector<std::vector<double>>& wall, std::vector<std::vector<double>>& cpu,
                         std::vector<std::vector<double>>& thread) {
  namespace md = marble::mesh_detail;
  const std::string file = path.string();
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  double w = wallMs(), c = cpuMs(), h = threadMs(), w0 = w, c0 = c, h0 = h;
  size_t phase = 0;
  auto lap = [&] {
    const double w1 = wallMs(), c1 = cpuMs(), h1 = threadMs();
    wall[phase].push_back(w1 - w);
    cpu[phase].push_back(c1 - c);
    thread[phase].push_back(h1 - h);
    w = w1;
    c = c1;
    h = h1;
    ++phase;
  };
  marble::FileBytes bytes = marble::InputFile(path, file, "a mesh file").readLarge(UINT64_MAX, md::kMaxFileBytes);
  const std::string_view data = bytes.view();
  lap();
  marble::Mesh mesh = ext == ".obj" ? md::loadObj(file, data) : ext == ".ply" ? md::loadPly(file, data) : md::loadStl(file, data);
  // As loadMesh: the file's pages kept for the normals' records when the file has no normals.
  marble::PageBuffer recycled = std::move(bytes.pages);
  if (!mesh.normals.empty()) recycled = {};
  lap();
  marble::applyUpAxis(mesh, up);
  marble::normalizeMesh(mesh, file);
  lap();
  const std::vector<uint32_t> points = marble::pointIds(mesh.positions);
  lap();
  // Without file normals the normals' pass drops the duplicates (as loadMesh does): then the
  // duplicates' column is empty and the normals' holds both.
  if (!mesh.normals.empty()) marble::removeDuplicateTriangles(mesh, points);
  lap();
  if (mesh.normals.empty()) marble::removeDuplicatesAndComputeNormals(mesh, crease, points, &recycled);
  lap();
  wall[phase].push_back(wallMs() - w0);
  cpu[phase].push_back(cpuMs() - c0);
  thread[phase].push_back(threadMs() - h0);
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  marble::keepFreedMemoryForReuse();  // as `marble` runs
  int runs = 5;
  marble::MeshLoadOptions options;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--up" && i + 1 < argc) options.up = marble::parseUpAxis(argv[++i]);
    else if (a == "--crease" && i + 1 < argc) options.creaseAngleDeg = std::strtof(argv[++i], nullptr);
    else files.emplace_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: marble_load_phases [--runs N] [--up AXIS] [--crease DEG] FILE...\n");
    return 2;
  }
  using Samples = std::vector<std::vector<double>>;
  std::vector<Samples> wall(files.size(), Samples(kPhaseCount)), cpu = wall, thread = wall;
  try {
    std::vector<std::string> warnings;
    options.warnings = &warnings;
    for (size_t f = 0; f < files.size(); ++f) {
      Samples w(kPhaseCount), c(kPhaseCount), h(kPhaseCount);
      if (!sameMesh(loadInSteps(files[f], options.up, options.creaseAngleDeg, w, c, h), marble::loadMesh(files[f], options))) {
        std::fprintf(stderr, "marble_load_phases: %s: the steps differ from loadMesh\n", files[f].string().c_str());
        return 1;
      }
    }
    for (int r = 0; r < runs; ++r)
      for (size_t f = 0; f < files.size(); ++f) {
        loadInSteps(files[f], options.up, options.creaseAngleDeg, wall[f], cpu[f], thread[f]);
        const double w0 = wallMs(), c0 = cpuMs(), h0 = threadMs();
        marble::loadMesh(files[f], options);
        wall[f][kPhaseCount - 1].push_back(wallMs() - w0);
        cpu[f][kPhaseCount - 1].push_back(cpuMs() - c0);
        thread[f][kPhaseCount - 1].push_back(threadMs() - h0);
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "marble_load_phases: %s\n", e.what());
    return 2;
  }
  std::printf("median of %d interleaved runs; ms CPU (all threads) / ms CPU (calling thread) / ms wall\n\n| file |", runs);
  for (const char* p : kPhases) std::printf(" %s |", p);
  std::printf("\n| --- |");
  for (size_t p = 0; p < kPhaseCount; ++p) std::printf(" ---: |");
  std::printf("\n");
  for (size_t f = 0; f < files.size(); ++f) {
    std::printf("| %s |", files[f].filename().string().c_str());
    for (size_t p = 0; p < kPhaseCount; ++p) std::printf(" %.0f / %.0f / %.0f |", median(cpu[f][p]), median(thread[f][p]), median(wall[f][p]));
    std::printf("\n");
  }
  return 0;
}
