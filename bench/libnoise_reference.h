#pragma once
// The libnoise Perlin module both CPU benchmarks compare the vein rows with (bench/noise_bench.cpp,
// bench/row_min.cpp), set up once so the two measure the same thing: 6 octaves at period 32,
// lacunarity 2, persistence 0.5 (the same octave sizes 32 ... 1 as marble's turbulence).
// libnoise's headers (include dir /usr/include/libnoise, not a system dir) have unused
// parameters; keep -Wextra -Werror builds clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <noise.h>
#pragma GCC diagnostic pop

namespace marble::bench {

inline void configureReferencePerlin(noise::module::Perlin& perlin) {
  perlin.SetOctaveCount(6);
  perlin.SetFrequency(1.0 / 32.0);
  perlin.SetLacunarity(2.0);
  perlin.SetPersistence(0.5);
  perlin.SetSeed(1);
}

}  // namespace marble::bench
