// The marble pattern on the CPU against libnoise (Debian's libnoise-dev), same points, same
// octave count. docs/performance.md ("Marble pattern on the CPU") records the method and results.
//
// Points: a 256 x 256 grid of texel positions (x, y, z0) of the solid pattern (3D), texel
// spacing 1: what baking a texture or a volume slice evaluates. Octaves: turb_size = 32 gives
// sizes 32, 16, 8, 4, 2, 1 = 6 octaves; libnoise's Perlin module gets SetOctaveCount(6),
// frequency 1/32 per texel, lacunarity 2, persistence 0.5 (each octave half the weight of the
// previous: the same weights as the paper's turbulence), default quality (cubic s-curve).
//
// The vein model (issue 16) runs the Carrara preset on the same points: evaluated by rows, and
// with its turbulence read from the baked vein grid (the grid's bake measured on its own).
//
// Each benchmark evaluates all 65,536 points per iteration; the counter "samples/s" is points
// per second of wall time. "/threads:2" variants split the rows over std::threads.
#include <benchmark/benchmark.h>
#include "libnoise_reference.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "marble/noise/marble_pattern.h"
#include "marble/noise/turbulence_grid.h"
#include "marble/scene/material_io.h"

namespace {

using marble::Material;

constexpr int kGrid = 256;
constexpr float kZ = 37.25f;

Material benchMaterial(marble::NoiseBasis basis) {
  Material m;
  m.basis = basis;
  m.turb_size = 32.0f;
  m.resolution = 256;
  return m;
}

// Calls rowFn(y, out) for rows split into `threads` interleaved sets.
template <typename RowFn>
void forRows(int threads, std::vector<float>& out, RowFn rowFn) {
  auto work = [&](int first) {
    for (int y = first; y < kGrid; y += threads) rowFn(y, &out[static_cast<size_t>(y) * kGrid]);
  };
  if (threads <= 1) {
    work(0);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
}

template <typename RowFn>
void runGrid(benchmark::State& state, RowFn rowFn) {
  const int threads = static_cast<int>(state.range(0));
  std::vector<float> out(static_cast<size_t>(kGrid) * kGrid);
  for (auto _ : state) {
    forRows(threads, out, rowFn);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["samples/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kGrid * kGrid, benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
}

const std::vector<float>& rowXs() {
  static const std::vector<float> xs = [] {
    std::vector<float> v(kGrid);
    for (int i = 0; i < kGrid; ++i) v[static_cast<size_t>(i)] = static_cast<float>(i);
    return v;
  }();
  return xs;
}

// libnoise: Perlin, 6 octaves, 3D.
void BM_Libnoise_Perlin3D(benchmark::State& state) {
  noise::module::Perlin perlin;
  marble::bench::configureReferencePerlin(perlin);
  runGrid(state, [&](int y, float* out) {
    for (int x = 0; x < kGrid; ++x) out[x] = static_cast<float>(perlin.GetValue(x, y, kZ));
  });
}

// Ours, one point at a time (the reference the GPU is tested against): value basis.
void BM_Marble_Turbulence3D_PerPoint_Value(benchmark::State& state) {
  const Material m = benchMaterial(marble::NoiseBasis::Value);
  runGrid(state, [&](int y, float* out) {
    for (int x = 0; x < kGrid; ++x) out[x] = marble::turbulence3(m, {static_cast<float>(x), static_cast<float>(y), kZ});
  });
}

// Ours, one point at a time: Perlin's improved noise (gradient noise, like libnoise's).
void BM_Marble_Turbulence3D_PerPoint_Perlin(benchmark::State& state) {
  const Material m = benchMaterial(marble::NoiseBasis::Perlin);
  runGrid(state, [&](int y, float* out) {
    for (int x = 0; x < kGrid; ++x) out[x] = marble::turbulence3(m, {static_cast<float>(x), static_cast<float>(y), kZ});
  });
}

// Ours, a row at a time (lattice columns computed once per cell): value basis.
void BM_Marble_Turbulence3D_Rows_Value(benchmark::State& state) {
  const Material m = benchMaterial(marble::NoiseBasis::Value);
  runGrid(state, [&](int y, float* out) {
    marble::patternRow3(m, rowXs().data(), static_cast<float>(y), kZ, kGrid, out, nullptr);
  });
}

// The whole pattern (turbulence + sine), a row at a time: what `marble texture` runs.
void BM_Marble_Pattern3D_Rows_Value(benchmark::State& state) {
  const Material m = benchMaterial(marble::NoiseBasis::Value);
  runGrid(state, [&](int y, float* out) {
    marble::patternRow3(m, rowXs().data(), static_cast<float>(y), kZ, kGrid, nullptr, out);
  });
}

// How the vein rows shaded their points on this thread (threads:1 only: the counts are per
// thread): the share of 8-point batches whose lanes branched differently and were recomputed
// one point at a time, and whether the 8-lane (AVX2) path ran at all.
void reportLanes(benchmark::State& state, const marble::VeinRowCounts& before) {
  const marble::VeinRowCounts after = marble::veinRowCounts();
  const double batches = static_cast<double>(after.laneBatches - before.laneBatches);
  state.counters["lanes"] = marble::veinRowsUseLanes() ? 8 : 1;
  if (state.range(0) == 1 && batches > 0)
    state.counters["diverged"] = static_cast<double>(after.divergedBatches - before.divergedBatches) / batches;
}

// The vein model (issue 16), a row at a time: the Carrara preset's colour at the same grid of
// points (object space: texel / 128 - 1, so the 256 x 256 points span the object), four
// turbulence samples by rows plus three Voronoi families per point: what `marble texture`
// runs for a stone preset.
void BM_Marble_Veins3D_Rows(benchmark::State& state) {
  const Material m = marble::loadPreset("carrara");
  std::vector<glm::vec3> colours(kGrid);
  const marble::VeinRowCounts before = marble::veinRowCounts();
  runGrid(state, [&](int y, float* out) {
    const glm::vec3 origin(-1.0f, static_cast<float>(y) / 128.0f - 1.0f, kZ / 128.0f - 1.0f);
    marble::veinAlbedoRow(m, origin, glm::vec3(1.0f / 128.0f, 0.0f, 0.0f), kGrid, colours.data(), out);
  });
  reportLanes(state, before);
}

// The same rows with the four turbulence samples read from the vein grid on the CPU
// (AlbedoSampler::veinRow: the (W/2)^3 four-channel grid the GPU samples, baked once per
// seed/resolution/turb_size, as the renderer keeps it; its bake is BM_Marble_VeinGrid_Bake).
void BM_Marble_Veins3D_Rows_Grid(benchmark::State& state) {
  const Material m = marble::loadPreset("carrara");
  static const marble::AlbedoSampler sampler(m, 1e12);  // points enough to pay for the grid
  std::vector<glm::vec3> colours(kGrid);
  const marble::VeinRowCounts before = marble::veinRowCounts();
  runGrid(state, [&](int y, float* out) {
    const glm::vec3 origin(-1.0f, static_cast<float>(y) / 128.0f - 1.0f, kZ / 128.0f - 1.0f);
    sampler.veinRow(origin, glm::vec3(1.0f / 128.0f, 0.0f, 0.0f), kGrid, colours.data(), out);
  });
  reportLanes(state, before);
}

// Baking that grid (128^3 texels x 4 samples for carrara: W = 256), on all cores.
void BM_Marble_VeinGrid_Bake(benchmark::State& state) {
  const Material m = marble::loadPreset("carrara");
  for (auto _ : state) benchmark::DoNotOptimize(marble::bakeTurbulenceGrid(m).data());
}

const int kThreads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

#define MARBLE_BENCH(fn) BENCHMARK(fn)->Arg(1)->Arg(kThreads)->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond)
MARBLE_BENCH(BM_Libnoise_Perlin3D);
MARBLE_BENCH(BM_Marble_Turbulence3D_PerPoint_Perlin);
MARBLE_BENCH(BM_Marble_Turbulence3D_PerPoint_Value);
MARBLE_BENCH(BM_Marble_Turbulence3D_Rows_Value);
MARBLE_BENCH(BM_Marble_Pattern3D_Rows_Value);
MARBLE_BENCH(BM_Marble_Veins3D_Rows);
MARBLE_BENCH(BM_Marble_Veins3D_Rows_Grid);
BENCHMARK(BM_Marble_VeinGrid_Bake)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
