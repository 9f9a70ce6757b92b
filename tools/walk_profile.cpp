// The radial profile of the random walk Blender Cycles 3.4 runs for RANDOM_WALK subsurface
// scattering, in a half-space of stone lit at one point: where the light that entered comes out.
// It gives the `marble` mode's screen-space blur its width (src/marble/render/subsurface_profile.*).
//
//     g++ -O2 -std=c++17 -o walk_profile tools/walk_profile.cpp && ./walk_profile    # ~2 minutes
//     ./walk_profile --axis-cdf    # section 3 alone, ~40 s
//
// The walk is tools/slab_walk_table.py's (cosine-weighted entry, exponential flights of mean
// 1/sigma_t, isotropic scattering weighted by the single-scattering albedo alpha, no reflection
// inside the boundary, dropped after 256 flights: Cycles' BSSRDF_MAX_BOUNCES), with no far face.
// Prints:
// 1. per albedo row u = -log10(1 - alpha): the exit radius's percentiles in mean free paths, and
//    the d / l for which Burley's normalized diffusion (Christensen & Burley 2015), whose radial
//    CDF is 1 - e^(-r/d)/4 - 3 e^(-r/(3d))/4, best matches the walk's CDF between its 5th and 98th
//    percentiles (least squares; "cdf-rms" the residual): kRowDOverL in subsurface_profile.cpp;
// 2. for the stone (sigma_a, sigma_s per mm of principled-white), E[x^2] of the exit
//    points along one axis within |x| <= 6.51 mm, the blur's reach there:
//    kWalkAxisSecondMomentMm2 in tests/subsurface_profile_test.cpp;
// 3. per albedo row, the walk's 1D marginal as a CDF: the share of the light that entered at the
//    origin and leaves with |x| <= t mean free paths, at the t of kAxisT (400,000 walks per row,
//    x and y both counted): kAxisCdf in subsurface_profile.cpp, the blur's weights out to the
//    walk's far tail (docs/quality.md, "Eighteenth session: the side-lit shade").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {
constexpr int kCap = 256;
constexpr double kPi = 3.14159265358979323846;

struct Exit {
  double x, y, weight;
};

// One walk from the origin into z > 0, sigma_t = 1; false if dropped at the cap.
bool walk(double alpha, std::mt19937_64& rng, Exit& out) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double x = 0, y = 0, z = 0, w = 1;
  const double mu = std::sqrt(u(rng)), phi = 2 * kPi * u(rng), s = std::sqrt(1 - mu * mu);
  double dx = s * std::cos(phi), dy = s * std::sin(phi), dz = mu;
  for (int b = 0; b < kCap; ++b) {
    const double t = -std::log(1 - u(rng));
    const double nz = z + dz * t;
    if (nz < 0) {
      const double q = -z / dz;
      out = {x + dx * q, y + dy * q, w};
      return true;
    }
    x += dx * t;
    y += dy * t;
    z = nz;
    w *= alpha;
    const double c = 2 * u(rng) - 1, p = 2 * kPi * u(rng), sn = std::sqrt(1 - c * c);
    dx = sn * std::cos(p);
    dy = sn * std::sin(p);
    dz = c;
  }
  return false;
}

double burleyCdf(double r) { return 1 - 0.25 * std::exp(-r) - 0.75 * std::exp(-r / 3); }

void fitRows() {
  std::mt19937_64 rng(11);
  const double rows[] = {0.5, 1, 1.5, 2, 2.25, 2.5, 2.75, 3, 3.5, 4, 5, 6};
  for (double row : rows) {
    const double alpha = 1 - std::pow(10.0, -row);
    const int n = 200000;
    std::vector<std::pair<double, double>> exits;  // radius, weight
    double total = 0;
    for (int i = 0; i < n; ++i) {
      Exit e;
      if (walk(alpha, rng, e)) {
        exits.push_back({std::hypot(e.x, e.y), e.weight});
        total += e.weight;
      }
    }
    std::sort(exits.begin(), exits.end());
    std::vector<double> r, cdf;
    double cum = 0;
    for (const auto& e : exits) {
      cum += e.second;
      r.push_back(e.first);
      cdf.push_back(cum / total);
    }
    auto quantile = [&](double q) { return r[std::lower_bound(cdf.begin(), cdf.end(), q) - cdf.begin()]; };
    double best = 0, bestErr = 1e30;
    for (double d = 0.2; d < 20; d *= 1.002) {
      double err = 0;
      for (double q = 0.05; q < 0.99; q += 0.01) err += std::pow(burleyCdf(quantile(q) / d) - q, 2);
      if (err < bestErr) bestErr = err, best = d;
    }
    std::printf("u %.2f alpha %.6f R %.4f  r50 %.2f r90 %.2f r95 %.2f r99 %.2f (mean free paths)  d/l %.3f  cdf-rms %.4f\n",
                row, alpha, total / n, quantile(0.5), quantile(0.9), quantile(0.95), quantile(0.99), best,
                std::sqrt(bestErr / 94));
  }
}

void stoneMoments() {
  std::mt19937_64 rng(7);
  const double sigmaA[3] = {0.00303, 0.00671, 0.0170}, sigmaS[3] = {1.252, 1.771, 2.049};  // per mm
  const double reachMm = 6.51;
  const int n = 400000;
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = sigmaA[c] + sigmaS[c];
    double m2 = 0, w = 0;
    for (int i = 0; i < n; ++i) {
      Exit e;
      if (!walk(sigmaS[c] / sigmaT, rng, e)) continue;
      const double xMm = e.x / sigmaT;
      if (std::fabs(xMm) <= reachMm) m2 += e.weight * xMm * xMm, w += e.weight;
    }
    std::printf("stone channel %d: E[x^2 | |x| <= %.2f mm] = %.3f mm^2\n", c, reachMm, m2 / w);
  }
}
void axisCdfRows() {
  std::mt19937_64 rng(13);
  const double rows[] = {0.5, 1, 1.5, 2, 2.25, 2.5, 2.75, 3, 3.5, 4, 5, 6};
  const double ts[] = {0, 0.25, 0.5, 0.75, 1, 1.5, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 40, 48};
  constexpr int kT = sizeof(ts) / sizeof(ts[0]);
  std::printf("axis CDF rows (share with |x| <= t mean free paths), t = 0");
  for (int j = 1; j < kT; ++j) std::printf(", %g", ts[j]);
  std::printf(":\n");
  for (double row : rows) {
    const double alpha = 1 - std::pow(10.0, -row);
    const int n = 400000;
    double inside[kT] = {0}, total = 0;
    for (int i = 0; i < n; ++i) {
      Exit e;
      if (!walk(alpha, rng, e)) continue;
      for (double x : {std::fabs(e.x), std::fabs(e.y)}) {
        total += e.weight;
        for (int j = 0; j < kT; ++j)
          if (x <= ts[j]) inside[j] += e.weight;
      }
    }
    std::printf("    {");
    for (int j = 0; j < kT; ++j) std::printf("%s%.5ff", j ? ", " : "", inside[j] / total);
    std::printf("},  // u %g\n", row);
  }
}
}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--axis-cdf") {  // section 3 alone
    axisCdfRows();
    return 0;
  }
  fitRows();
  stoneMoments();
  axisCdfRows();
}
