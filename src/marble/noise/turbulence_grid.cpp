#include "marble/noise/turbulence_grid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "marble/noise/marble_pattern.h"

namespace marble {
namespace {

bool isPowerOfTwo(float size) {
  if (size < 1.0f || size != std::floor(size)) return false;
  const auto n = static_cast<uint32_t>(size);
  return (n & (n - 1u)) == 0u;
}

uint16_t toUnorm16(float turbulence) {
  return static_cast<uint16_t>(std::lround(std::clamp(turbulence, 0.0f, 1.0f) * 65535.0f));
}

}  // namespace

int turbulenceGridDimensions(const Material& m) {
  if (m.basis != NoiseBasis::Value) return 0;
  // Every octave size (turb_size, /2, ..., 1) an integer dividing W: turb_size a power of two
  // dividing W (pattern_core.glsl: an octave of size s has W/s lattice cells when s divides W).
  if (!isPowerOfTwo(m.turb_size) || m.resolution % static_cast<int>(m.turb_size) != 0) return 0;
  // The vein models are solid whatever the mapping (pattern_core.glsl "vein networks"); their
  // grid's texels are 2 texels apart, which needs an octave of at least 2 texels.
  if (m.vein_model != VeinModel::Paper)
    return m.turb_size >= 2.0f && m.resolution / 2 <= kMaxVeinTurbulenceGrid ? 3 : 0;
  if (m.mapping == PatternMapping::Solid) return m.resolution <= kMaxSolidTurbulenceGrid ? 3 : 0;
  return 2;
}

TurbulenceGridKey turbulenceGridKey(const Material& m) {
  return {m.seed, m.resolution, m.turb_size, turbulenceGridDimensions(m), m.vein_model != VeinModel::Paper};
}

int turbulenceGridSize(const Material& m) { return m.vein_model != VeinModel::Paper ? m.resolution / 2 : m.resolution; }
int turbulenceGridChannels(const Material& m) { return m.vein_model != VeinModel::Paper ? 4 : 1; }

std::vector<uint16_t> bakeTurbulenceGrid(const Material& m) {
  const int dims = turbulenceGridDimensions(m);
  if (dims == 0) throw std::logic_error("bakeTurbulenceGrid: this material's turbulence has no exact grid");
  const int w = turbulenceGridSize(m);
  const int channels = turbulenceGridChannels(m);
  const bool veins = m.vein_model != VeinModel::Paper;
  const float spacing = veins ? 2.0f : 1.0f;  // texel points between grid texels
  const int rows = dims == 3 ? w * w : w;     // rows of w grid texels along x
  std::vector<uint16_t> grid(static_cast<size_t>(rows) * static_cast<size_t>(w) * static_cast<size_t>(channels));

  // Rows handed out one at a time: every thread writes only its own rows.
  std::atomic<int> nextRow{0};
  auto work = [&] {
    std::vector<float> turbulence(static_cast<size_t>(w));
    std::vector<float> xs(static_cast<size_t>(w));
    for (int row = nextRow++; row < rows; row = nextRow++) {
      uint16_t* out = grid.data() + static_cast<size_t>(row) * static_cast<size_t>(w) * static_cast<size_t>(channels);
      for (int k = 0; k < channels; ++k) {
        const glm::vec3 offset = veins ? veinSampleOffset(m, k) : glm::vec3(0.0f);
        for (int x = 0; x < w; ++x) xs[static_cast<size_t>(x)] = static_cast<float>(x) * spacing + offset.x;
        const float y = static_cast<float>(row % w) * spacing + offset.y;
        const float z = static_cast<float>(row / w) * spacing + offset.z;
        if (veins)
          veinTurbulenceRow(m, xs.data(), y, z, w, turbulence.data());
        else if (dims == 3)
          patternRow3(m, xs.data(), y, z, w, turbulence.data(), nullptr);
        else
          patternRow2(m, xs.data(), y, w, turbulence.data(), nullptr);
        for (int x = 0; x < w; ++x)
          out[static_cast<size_t>(x) * static_cast<size_t>(channels) + static_cast<size_t>(k)] =
              toUnorm16(turbulence[static_cast<size_t>(x)]);
      }
    }
  };
  const unsigned threads = dims == 3 ? std::clamp(std::thread::hardware_concurrency(), 1u, 16u) : 1u;
  std::vector<std::thread> helpers;
  for (unsigned i = 1; i < threads; ++i) helpers.emplace_back(work);
  work();
  for (std::thread& t : helpers) t.join();
  return grid;
}

}  // namespace marble
