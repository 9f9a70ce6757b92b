#pragma once
// Measures of what makes veins read as real stone (issue 16), on a grey image of the pattern's
// value before colour (`marble texture`'s veins.png for the vein models, sine.png for the
// paper's: both 0 at a vein's heart, 1 in the ground):
//
//   branching  junctions of the vein network per 1000 pixels of its skeleton,
//   width CV   how much a vein's width varies along it (median over veins of std/mean),
//   endings    veins that end inside the picture (skeleton end points away from the border).
//
// Why a naive skeleton junction count does not tell a network from contour lines: the bands
// of |sin(ramp + turbulence)| have bumps (each a short spur on the skeleton, ending in a
// junction) and pinholes (each a small loop: two junctions). So, before counting:
//   0. the value is blurred (Gaussian, sigma 0.8 px): the bands' frost-like fringes go;
//   1. the mask (value < threshold) loses specks under kMinSpeck pixels and has its holes under
//      kMaxHole pixels filled (no pinhole loops);
//   2. it is thinned (Zhang & Suen 1984) to a one-pixel skeleton;
//   3. spurs are pruned: end points (and the stray corner pixels thinning leaves at a tip: any
//      pixel whose neighbours form one run, crossing number 1) are peeled kPrune times, so every
//      branch shorter than kPrune pixels disappears with its junction, and longer ones only get
//      shorter; ends within kBorder of the edge are kept (veins leaving the picture);
//   4. a junction is a skeleton pixel whose 8 neighbours, walked in a circle, change from
//      background to skeleton 3 or more times (the crossing number); touching junction pixels
//      count once.
// A vein is then a piece of the pruned skeleton between junctions and end points; its width at
// each pixel is twice the distance to the background (chamfer 3-4 distance transform).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace marble::test {

struct VeinStructure {
  int skeletonPixels = 0;
  int junctions = 0;
  double junctionsPer1000 = 0.0;  // branching
  double widthCv = 0.0;           // median over veins of at least kMinVein pixels
  int veinsMeasured = 0;
  int innerEndings = 0;           // end points more than kBorder pixels from the edge
};

namespace vein_detail {

constexpr int kMinSpeck = 20;
constexpr int kMaxHole = 300;
constexpr int kPrune = 20;
constexpr float kBlurSigma = 0.8f;
constexpr int kMinVein = 30;
constexpr int kBorder = 8;

struct Grid {
  int w = 0, h = 0;
  std::vector<uint8_t> v;
  uint8_t at(int x, int y) const { return x < 0 || y < 0 || x >= w || y >= h ? 0 : v[static_cast<size_t>(y) * w + x]; }
  uint8_t& ref(int x, int y) { return v[static_cast<size_t>(y) * w + x]; }
};

// Neighbours in circular order P2..P9 (N, NE, E, SE, S, SW, W, NW).
constexpr int kDx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr int kDy[8] = {-1, -1, 0, 1, 1, 1, 0, -1};

inline int neighbours(const Grid& g, int x, int y) {
  int n = 0;
  for (int k = 0; k < 8; ++k) n += g.at(x + kDx[k], y + kDy[k]) ? 1 : 0;
  return n;
}
inline int crossings(const Grid& g, int x, int y) {
  int c = 0;
  for (int k = 0; k < 8; ++k) c += !g.at(x + kDx[k], y + kDy[k]) && g.at(x + kDx[(k + 1) % 8], y + kDy[(k + 1) % 8]) ? 1 : 0;
  return c;
}

// Labels the 8-connected (value == want) components; calls f(pixels, touchesBorder) for each.
template <typename F>
void components(const Grid& g, uint8_t want, F f) {
  std::vector<uint8_t> seen(g.v.size(), 0);
  std::vector<int> stack, pix;
  for (int start = 0; start < g.w * g.h; ++start) {
    if (seen[static_cast<size_t>(start)] || (g.v[static_cast<size_t>(start)] != 0) != (want != 0)) continue;
    pix.clear();
    stack.assign(1, start);
    seen[static_cast<size_t>(start)] = 1;
    bool border = false;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      pix.push_back(i);
      const int x = i % g.w, y = i / g.w;
      if (x == 0 || y == 0 || x == g.w - 1 || y == g.h - 1) border = true;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (nx < 0 || ny < 0 || nx >= g.w || ny >= g.h) continue;
        const int j = ny * g.w + nx;
        if (seen[static_cast<size_t>(j)] || (g.v[static_cast<size_t>(j)] != 0) != (want != 0)) continue;
        seen[static_cast<size_t>(j)] = 1;
        stack.push_back(j);
      }
    }
    f(pix, border);
  }
}

inline void thin(Grid& g) {  // Zhang & Suen 1984
  std::vector<int> del;
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      del.clear();
      for (int y = 0; y < g.h; ++y)
        for (int x = 0; x < g.w; ++x) {
          if (!g.at(x, y)) continue;
          const int b = neighbours(g, x, y);
          if (b < 2 || b > 6 || crossings(g, x, y) != 1) continue;
          const int p2 = g.at(x, y - 1), p4 = g.at(x + 1, y), p6 = g.at(x, y + 1), p8 = g.at(x - 1, y);
          if (pass == 0 ? (p2 && p4 && p6) || (p4 && p6 && p8) : (p2 && p4 && p8) || (p2 && p6 && p8)) continue;
          del.push_back(y * g.w + x);
        }
      for (int i : del) g.v[static_cast<size_t>(i)] = 0;
      changed = changed || !del.empty();
    }
  }
}

// A Gaussian blur (sigma kBlurSigma pixels, separable, edges clamped): the bands' frost-like
// fringes (the finest octaves) would otherwise thin to a thicket of spurs.
inline std::vector<float> blurred(const std::vector<float>& v, int w, int h) {
  constexpr int r = 4;
  float k[2 * r + 1], sum = 0;
  for (int i = -r; i <= r; ++i) sum += k[i + r] = std::exp(-0.5f * i * i / (kBlurSigma * kBlurSigma));
  for (float& x : k) x /= sum;
  std::vector<float> t(v.size()), out(v.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float a = 0;
      for (int i = -r; i <= r; ++i) a += k[i + r] * v[static_cast<size_t>(y) * w + std::clamp(x + i, 0, w - 1)];
      t[static_cast<size_t>(y) * w + x] = a;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float a = 0;
      for (int i = -r; i <= r; ++i) a += k[i + r] * t[static_cast<size_t>(std::clamp(y + i, 0, h - 1)) * w + x];
      out[static_cast<size_t>(y) * w + x] = a;
    }
  return out;
}

// Chamfer 3-4 distance to the background, in pixels.
inline std::vector<float> distanceToBackground(const Grid& g) {
  const float inf = 1e9f;
  std::vector<float> d(g.v.size());
  for (size_t i = 0; i < d.size(); ++i) d[i] = g.v[i] ? inf : 0.0f;
  auto D = [&](int x, int y) { return x < 0 || y < 0 || x >= g.w || y >= g.h ? 0.0f : d[static_cast<size_t>(y) * g.w + x]; };
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) {
      float& c = d[static_cast<size_t>(y) * g.w + x];
      if (c == 0.0f) continue;
      c = std::min({c, D(x - 1, y) + 3, D(x, y - 1) + 3, D(x - 1, y - 1) + 4, D(x + 1, y - 1) + 4});
    }
  for (int y = g.h - 1; y >= 0; --y)
    for (int x = g.w - 1; x >= 0; --x) {
      float& c = d[static_cast<size_t>(y) * g.w + x];
      if (c == 0.0f) continue;
      c = std::min({c, D(x + 1, y) + 3, D(x, y + 1) + 3, D(x + 1, y + 1) + 4, D(x - 1, y + 1) + 4});
    }
  for (float& c : d) c /= 3.0f;
  return d;
}

}  // namespace vein_detail

// value: w * h values in [0,1] (row 0 the top), 0 = vein; a pixel is vein where value <
// threshold: where its colour is nearer the vein's than the ground's (0.5 for the vein models'
// coverage; 0.5^vein_sharpness for the paper's ramp, whose midpoint is at t = v^(1/s) = 0.5).
inline VeinStructure measureVeins(const std::vector<float>& value, int w, int h, float threshold = 0.5f) {
  using namespace vein_detail;
  const std::vector<float> smooth = blurred(value, w, h);
  Grid mask{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h)};
  for (size_t i = 0; i < mask.v.size(); ++i) mask.v[i] = smooth[i] < threshold ? 1 : 0;
  // 1. specks and pinholes.
  components(mask, 1, [&](const std::vector<int>& pix, bool) {
    if (static_cast<int>(pix.size()) < kMinSpeck)
      for (int i : pix) mask.v[static_cast<size_t>(i)] = 0;
  });
  components(mask, 0, [&](const std::vector<int>& pix, bool border) {
    if (!border && static_cast<int>(pix.size()) < kMaxHole)
      for (int i : pix) mask.v[static_cast<size_t>(i)] = 1;
  });
  const std::vector<float> dist = distanceToBackground(mask);
  // 2. skeleton.
  Grid skel = mask;
  thin(skel);
  // 3. prune spurs: peel end points kPrune times (not those at the border: veins that leave
  // the picture are not spurs).
  auto nearBorder = [&](int x, int y) { return x < kBorder || y < kBorder || x >= w - kBorder || y >= h - kBorder; };
  for (int it = 0; it < kPrune; ++it) {
    std::vector<int> ends;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (skel.at(x, y) && crossings(skel, x, y) <= 1 && neighbours(skel, x, y) <= 3 && !nearBorder(x, y)) ends.push_back(y * w + x);
    for (int i : ends) skel.v[static_cast<size_t>(i)] = 0;
  }
  VeinStructure r;
  // 4. junctions (clusters of touching junction pixels), end points, veins.
  Grid junction{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!skel.at(x, y)) continue;
      ++r.skeletonPixels;
      if (crossings(skel, x, y) >= 3) junction.ref(x, y) = 1;
      if (neighbours(skel, x, y) == 1 && !nearBorder(x, y)) ++r.innerEndings;
    }
  components(junction, 1, [&](const std::vector<int>&, bool) { ++r.junctions; });
  r.junctionsPer1000 = r.skeletonPixels > 0 ? 1000.0 * r.junctions / r.skeletonPixels : 0.0;
  // Veins: the skeleton without the junctions' neighbourhoods (where widths merge).
  Grid veins = skel;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (junction.at(x, y))
        for (int dy = -3; dy <= 3; ++dy)
          for (int dx = -3; dx <= 3; ++dx)
            if (x + dx >= 0 && y + dy >= 0 && x + dx < w && y + dy < h) veins.ref(x + dx, y + dy) = 0;
  std::vector<double> cvs;
  components(veins, 1, [&](const std::vector<int>& pix, bool) {
    if (static_cast<int>(pix.size()) < kMinVein) return;
    double sum = 0, sum2 = 0;
    for (int i : pix) {
      const double width = 2.0 * dist[static_cast<size_t>(i)];
      sum += width;
      sum2 += width * width;
    }
    const double n = static_cast<double>(pix.size());
    const double mean = sum / n;
    cvs.push_back(std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean);
  });
  r.veinsMeasured = static_cast<int>(cvs.size());
  if (!cvs.empty()) {
    std::nth_element(cvs.begin(), cvs.begin() + static_cast<long>(cvs.size() / 2), cvs.end());
    r.widthCv = cvs[cvs.size() / 2];
  }
  return r;
}

}  // namespace marble::test
