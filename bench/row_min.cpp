// The vein rows against libnoise by the quietest time of each row (docs/performance.md, "Eleventh
// session: what the rows' time is"). On a shared machine a whole iteration of 65,536 points
// (10-40 ms) is rarely left alone on its core, so Google Benchmark's times carry the other
// processes' cache pollution and preemptions; a single row of 256 points takes 20-80 us and many
// repetitions of it run uninterrupted. Each row of the benchmark's 256 x 256 grid (the same
// points as bench/noise_bench.cpp) is timed on its own, REPS times, the functions interleaved
// row by row; a function's time is the sum over rows of each row's fastest run. That is the
// time on a quiet core with warm caches, which is what both sides are compared at.
//
//   build/bench/marble_row_min [REPS] [ftz]     (default 200; `ftz`: flush denormals to zero
//   and read them as zero, a diagnostic of whether any of the three meets them: the rows'
//   results are then no longer the reference's where one would occur)
#include "libnoise_reference.h"

#include <xmmintrin.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "marble/noise/marble_pattern.h"
#include "marble/scene/material_io.h"

namespace {

constexpr int kGrid = 256;
constexpr float kZ = 37.25f;

struct Candidate {
  std::string name;
  std::function<void(int y, float* out)> row;
  std::vector<double> best = std::vector<double>(kGrid, std::numeric_limits<double>::infinity());
};

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 200;
  if (argc > 2 && std::string(argv[2]) == "ftz") _mm_setcsr(_mm_getcsr() | 0x8040);  // FTZ | DAZ
  noise::module::Perlin perlin;
  marble::bench::configureReferencePerlin(perlin);
  const marble::Material carrara = marble::loadPreset("carrara");
  const marble::AlbedoSampler sampler(carrara, 1e12);
  std::vector<glm::vec3> colours(kGrid);
  auto origin = [](int y) { return glm::vec3(-1.0f, static_cast<float>(y) / 128.0f - 1.0f, kZ / 128.0f - 1.0f); };
  const glm::vec3 step(1.0f / 128.0f, 0.0f, 0.0f);

  std::vector<Candidate> candidates;
  candidates.push_back({"libnoise Perlin, 6 octaves", [&](int y, float* out) {
                          for (int x = 0; x < kGrid; ++x) out[x] = static_cast<float>(perlin.GetValue(x, y, kZ));
                        }});
  candidates.push_back({"vein rows (veinAlbedoRow)", [&](int y, float* out) {
                          marble::veinAlbedoRow(carrara, origin(y), step, kGrid, colours.data(), out);
                        }});
  candidates.push_back({"vein rows from the grid (AlbedoSampler::veinRow)", [&](int y, float* out) {
                          sampler.veinRow(origin(y), step, kGrid, colours.data(), out);
                        }});

  std::vector<float> out(kGrid);
  for (int r = 0; r < reps; ++r)
    for (int y = 0; y < kGrid; ++y)
      for (Candidate& c : candidates) {
        const auto t0 = std::chrono::steady_clock::now();
        c.row(y, out.data());
        const auto t1 = std::chrono::steady_clock::now();
        c.best[static_cast<size_t>(y)] = std::min(c.best[static_cast<size_t>(y)], std::chrono::duration<double, std::milli>(t1 - t0).count());
      }
  double libnoise = 0.0;
  std::printf("%-52s %10s %12s\n", "65,536 points, 1 thread, fastest run of each row", "ms", "vs libnoise");
  for (const Candidate& c : candidates) {
    double sum = 0.0;
    for (double b : c.best) sum += b;
    if (libnoise == 0.0) libnoise = sum;
    std::printf("%-52s %10.3f %11.2fx\n", c.name.c_str(), sum, libnoise / sum);
  }
  return 0;
}
