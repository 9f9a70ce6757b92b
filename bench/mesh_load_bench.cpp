// Mesh loading and processing times. The paper's dragon (../shared/models, beside the source
// tree) is measured when present; the built-in sculpture, written out as OBJ, always is.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace {

std::filesystem::path sculptureObj() {
  static const std::filesystem::path path = [] {
    auto p = std::filesystem::temp_directory_path() / "marble_bench_sculpture.obj";
    marble::Mesh m = marble::builtinMesh("sculpture");
    std::ofstream out(p);
    char line[128];
    for (const glm::vec3& v : m.positions) {
      std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", v.x, v.y, v.z);
      out << line;
    }
    for (size_t t = 0; t < m.indices.size(); t += 3)
      out << "f " << m.indices[t] + 1 << ' ' << m.indices[t + 1] + 1 << ' ' << m.indices[t + 2] + 1 << '\n';
    return p;
  }();
  return path;
}

void BM_LoadObjSculpture(benchmark::State& state) {
  const auto path = sculptureObj();
  for (auto _ : state) benchmark::DoNotOptimize(marble::loadMesh(path));
  state.SetLabel(std::to_string(marble::loadMesh(path).triangleCount()) + " triangles");
}
BENCHMARK(BM_LoadObjSculpture)->Unit(benchmark::kMillisecond);

void BM_LoadObjDragon(benchmark::State& state) {
  const std::filesystem::path path = std::filesystem::path(MARBLE_SOURCE_DIR) / ".." / "shared" / "models" / "dragon.obj";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("../shared/models/dragon.obj not found");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(marble::loadMesh(path, marble::UpAxis::Z));
  state.SetLabel("100k triangles, Z-up");
}
BENCHMARK(BM_LoadObjDragon)->Unit(benchmark::kMillisecond);

void BM_BuiltinSculpture(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(marble::builtinMesh("sculpture"));
}
BENCHMARK(BM_BuiltinSculpture)->Unit(benchmark::kMillisecond);

// Angle-weighted normals with the default crease (welding, edge sort, fans). The sculpture has no
// edge past the crease, so every pass sees the same mesh.
void BM_VertexNormalsSculpture(benchmark::State& state) {
  marble::Mesh m = marble::builtinMesh("sculpture");
  for (auto _ : state) {
    marble::computeVertexNormals(m, marble::kDefaultCreaseAngleDeg);
    benchmark::DoNotOptimize(m.normals.data());
  }
}
BENCHMARK(BM_VertexNormalsSculpture)->Unit(benchmark::kMicrosecond);

}  // namespace
