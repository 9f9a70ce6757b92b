#pragma once
// Specular light from an environment, prefiltered once per map for a range of roughnesses
// (Karis 2013, "Real Shading in Unreal Engine 4", the split sum's first factor): each texel of
// level k holds the environment seen through the GGX lobe of alpha_k around its direction R,
// assuming N = V = R, integrated by importance-sampling GGX and weighting by N.L.
//
// Levels are the mip levels of one equirectangular texture: level 0 is the map (a mirror),
// level k >= 1 is filtered for alpha_k = alpha_1 2^(k-1) at half the previous level's size, so
// every level's lobe spans the same number of its texels: alpha_1 = 8 pi / W0 makes the lobe's
// half-width at half maximum (about 1.29 alpha) 2.6 texels of its level. The chain ends at the
// first level with alpha >= 1. The shader picks lod = 1 + log2(alpha / alpha_1), clamped.
#include <vector>

#include "marble/core/image.h"

namespace marble {

float prefilterAlpha1(int baseWidth);
// alpha_k of level k >= 1 (level 0 is unfiltered).
float prefilterAlpha(int level, int baseWidth);
// How many levels (>= 2) a map `baseWidth` wide gets.
int prefilterLevelCount(int baseWidth);

// Samples per texel: few, because each sample reads the source's mip chain at the footprint of
// its solid angle (filtered importance sampling: Krivanek and Colbert 2008, "Real-time Shading
// with Filtered Importance Sampling", GPU Gems 3 ch. 20, eq. 13), which removes the noise a few
// samples would otherwise leave. Levels of fewer than 2^20 / 32 texels get more, up to 16 times
// as many (same total cost per level): there a small bright source would otherwise fall
// unevenly on the few texels.
constexpr int kPrefilterSamples = 32;

// All levels, 0 (a copy of `base`) to prefilterLevelCount() - 1, computed on `threads` threads
// (0: one per hardware thread).
std::vector<ImageRGBF> prefilterGgx(const ImageRGBF& base, unsigned threads = 0, int samplesPerTexel = kPrefilterSamples);

}  // namespace marble
