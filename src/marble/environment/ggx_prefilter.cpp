#include "marble/environment/ggx_prefilter.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cmath>
#include <thread>

#include "marble/environment/equirect.h"

namespace marble {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One importance sample in the frame where N = V = R = +z: the light direction, its N.L
// weight, and half the log2 of the solid angle it stands for (filtered importance sampling).
struct LobeSample {
  glm::vec3 l;
  float weight;
  float halfLog2SolidAngle;
};

// Van der Corput radical inverse in base 2: the second Hammersley coordinate.
double radicalInverse(unsigned i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return static_cast<double>(i) * 2.3283064365386963e-10;
}

std::vector<LobeSample> lobeSamples(double alpha, int count) {
  const double a2 = alpha * alpha;
  std::vector<LobeSample> samples;
  for (int i = 0; i < count; ++i) {
    // GGX-distributed half vector (Walter et al. 2007, eqs. 35-36; Karis 2013, ImportanceSampleGGX).
    const double xi1 = (i + 0.5) / count, xi2 = radicalInverse(static_cast<unsigned>(i));
    const double phi = 2.0 * kPi * xi1;
    const double cosH = std::sqrt((1.0 - xi2) / (1.0 + (a2 - 1.0) * xi2));
    const double sinH = std::sqrt(1.0 - cosH * cosH);
    // L = reflect(-V, H) with V = +z.
    const glm::dvec3 h(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
    const glm::dvec3 l = 2.0 * cosH * h - glm::dvec3(0.0, 0.0, 1.0);
    if (l.z <= 0.0) continue;  // below the horizon of N: no contribution (Karis' N.L > 0 test)
    // pdf of L: D(H) (N.H) / (4 V.H) = D(H) / 4 when N = V; one sample stands for 1 / (count pdf).
    const double d = cosH * cosH * (a2 - 1.0) + 1.0;
    const double D = a2 / (kPi * d * d);
    const double solidAngle = 4.0 / (count * D);
    samples.push_back({glm::vec3(l), static_cast<float>(l.z), static_cast<float>(0.5 * std::log2(solidAngle))});
  }
  return samples;
}

// An orthonormal basis around unit n without branches on its direction (Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited", listing 3).
void basisAround(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// The inner loop runs tens of millions of times per map, so the equirectangular lookup uses
// polynomial arc tangent and arc cosine (Abramowitz and Stegun 4.4.49 and 4.4.45, Hastings'
// fits, errors below 1e-5 and 7e-5 radians: a fortieth of a 2048-wide map's texel).
float fastAtan01(float z) {  // atan(z) for z in [0, 1]
  const float z2 = z * z;
  return z * (0.9998660f + z2 * (-0.3302995f + z2 * (0.1801410f + z2 * (-0.0851330f + z2 * 0.0208351f))));
}
float fastAtan2(float y, float x) {
  const float ax = std::abs(x), ay = std::abs(y);
  const float hi = std::max(ax, ay);
  if (hi == 0.0f) return 0.0f;
  float a = fastAtan01(std::min(ax, ay) / hi);
  if (ay > ax) a = 1.5707963f - a;
  if (x < 0.0f) a = 3.1415927f - a;
  return y < 0.0f ? -a : a;
}
float fastAcos(float x) {
  const float ax = std::min(std::abs(x), 1.0f);
  const float a = std::sqrt(1.0f - ax) * (1.5707288f + ax * (-0.2121144f + ax * (0.0742610f - 0.0187293f * ax)));
  return x < 0.0f ? 3.1415927f - a : a;
}

// log2 for x > 0 from the float's exponent and a quadratic in its mantissa m in [1, 2)
// (error below 0.005, a lod error below 0.002 where it is used).
float fastLog2(float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  const float e = static_cast<float>(static_cast<int>((bits >> 23) & 0xFFu) - 127);
  const float m = std::bit_cast<float>((bits & 0x007FFFFFu) | 0x3F800000u);
  return e + (-0.34484843f * m + 2.02466578f) * m - 1.67487759f;
}

// equirectUv() with the polynomials: u in [0, 1], v in [0, 1].
glm::vec2 fastEquirectUv(const glm::vec3& d) {
  return {0.5f + fastAtan2(d.x, -d.z) * 0.15915494f, fastAcos(d.y) * 0.31830989f};
}

// sampleEquirect() for u in [0, 1] (no general wrap-around needed).
glm::vec3 bilinear(const ImageRGBF& img, const glm::vec2& uv) {
  const float x = uv.x * static_cast<float>(img.width) - 0.5f;
  const float y = std::clamp(uv.y * static_cast<float>(img.height) - 0.5f, 0.0f, static_cast<float>(img.height - 1));
  const int fx = static_cast<int>(std::floor(x)), y0 = static_cast<int>(y);
  const float tx = x - static_cast<float>(fx), ty = y - static_cast<float>(y0);
  const int x0 = fx < 0 ? fx + img.width : (fx >= img.width ? fx - img.width : fx);
  const int x1 = x0 + 1 == img.width ? 0 : x0 + 1;
  const int y1 = std::min(y0 + 1, img.height - 1);
  const glm::vec3 top = glm::mix(texelAt(img, x0, y0), texelAt(img, x1, y0), tx);
  const glm::vec3 bottom = glm::mix(texelAt(img, x0, y1), texelAt(img, x1, y1), tx);
  return glm::mix(top, bottom, ty);
}

// Bilinear between two mip levels of the source.
glm::vec3 sampleChain(const std::vector<ImageRGBF>& chain, const glm::vec2& uv, float lod) {
  lod = std::clamp(lod, 0.0f, static_cast<float>(chain.size() - 1));
  const int l0 = static_cast<int>(lod);
  const float t = lod - static_cast<float>(l0);
  const glm::vec3 a = bilinear(chain[static_cast<size_t>(l0)], uv);
  if (t <= 0.0f || l0 + 1 >= static_cast<int>(chain.size())) return a;
  return glm::mix(a, bilinear(chain[static_cast<size_t>(l0) + 1], uv), t);
}

void filterLevel(const std::vector<ImageRGBF>& chain, ImageRGBF& out, const std::vector<LobeSample>& samples,
                 unsigned threads) {
  const ImageRGBF& base = chain.front();
  // Solid angle of a base texel at the equator; at polar angle theta it is this times sin(theta).
  const float log2EquatorTexel = static_cast<float>(std::log2(2.0 * kPi / base.width * kPi / base.height));
  // Half a texel from the pole, where sin(theta) would reach 0.
  const float minSin2 = static_cast<float>(std::pow(std::sin(0.5 * kPi / base.height), 2.0));
  std::atomic<int> nextRow{0};
  auto work = [&] {
    for (int y; (y = nextRow.fetch_add(1)) < out.height;) {
      for (int x = 0; x < out.width; ++x) {
        const glm::vec3 r = equirectDirection((x + 0.5) / out.width, (y + 0.5) / out.height);
        glm::vec3 t, b;
        basisAround(r, t, b);
        glm::vec3 sum(0.0f);
        float wsum = 0.0f;
        for (const LobeSample& s : samples) {
          const glm::vec3 l = s.l.x * t + s.l.y * b + s.l.z * r;
          const float sin2 = std::max(1.0f - l.y * l.y, minSin2);
          // Krivanek and Colbert's lod: 0.5 log2(solid angle of the sample / of a texel) + 1.
          const float lod = s.halfLog2SolidAngle - 0.5f * (log2EquatorTexel + 0.5f * fastLog2(sin2)) + 1.0f;
          sum += s.weight * sampleChain(chain, fastEquirectUv(l), lod);
          wsum += s.weight;
        }
        float* p = &out.pixels[(static_cast<size_t>(y) * out.width + x) * 3];
        const glm::vec3 v = wsum > 0.0f ? sum / wsum : glm::vec3(0.0f);
        p[0] = v.r;
        p[1] = v.g;
        p[2] = v.b;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
}

}  // namespace

float prefilterAlpha1(int baseWidth) { return static_cast<float>(8.0 * kPi / baseWidth); }

float prefilterAlpha(int level, int baseWidth) {
  return level <= 0 ? 0.0f : prefilterAlpha1(baseWidth) * std::exp2(static_cast<float>(level - 1));
}

int prefilterLevelCount(int baseWidth) {
  int k = 1;
  while (prefilterAlpha(k, baseWidth) < 1.0f) ++k;
  return k + 1;
}

std::vector<ImageRGBF> prefilterGgx(const ImageRGBF& base, unsigned threads, int samplesPerTexel) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const std::vector<ImageRGBF> chain = equirectMipChain(base);
  const int count = prefilterLevelCount(base.width);
  std::vector<ImageRGBF> levels{base};
  for (int k = 1; k < count; ++k) {
    const int w = std::max(1, base.width >> k), h = std::max(1, base.height >> k);
    ImageRGBF level{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
    // Small levels (rough lobes, few texels) get more samples: they cost little there, and a
    // bright small source (a sun) then lands evenly on the few texels that share it.
    const int samples = std::clamp((1 << 20) / (w * h), samplesPerTexel, 16 * samplesPerTexel);
    filterLevel(chain, level, lobeSamples(prefilterAlpha(k, base.width), samples), threads);
    levels.push_back(std::move(level));
  }
  return levels;
}

}  // namespace marble
