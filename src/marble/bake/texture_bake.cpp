#include "marble/bake/texture_bake.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <thread>
#include <vector>

#include "marble/bake/ray_bvh.h"
#include "marble/bake/uv_raster.h"
#include "marble/noise/marble_pattern.h"

namespace marble {
namespace {

constexpr uint32_t kEmpty = ~0u;

uint8_t toByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

float linearToSrgb(float c) {  // IEC 61966-2-1
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Runs body(row) for rows [0, rows) on every hardware thread; the calling thread reports progress
// (fraction from `from` to `to`) and stops every thread when the callback asks to cancel.
void parallelRows(int rows, const BakeOptions& options, const char* stage, double from, double to,
                  const std::function<void(int)>& body) {
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> cancel{false};
  auto work = [&] {
    for (int r; !cancel.load(std::memory_order_relaxed) && (r = next.fetch_add(1)) < rows;) {
      body(r);
      done.fetch_add(1);
    }
  };
  const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  // The calling thread works too, reporting between rows.
  for (int r; !cancel.load() && (r = next.fetch_add(1)) < rows;) {
    body(r);
    done.fetch_add(1);
    if (options.progress && !options.progress(from + (to - from) * done.load() / rows, stage)) cancel = true;
  }
  for (auto& t : pool) t.join();
  if (cancel) throw BakeCancelled();
}

// Which triangle covers each cell's sample at `offset` (kEmpty: none).
std::vector<uint32_t> coverageIds(const Mesh& mesh, int res, glm::vec2 offset) {
  std::vector<uint32_t> ids(static_cast<size_t>(res) * res, kEmpty);
  for (uint32_t t = 0; t < mesh.triangleCount(); ++t)
    rasterizeUvTriangle(
        mesh.texcoords[mesh.indices[t * 3]], mesh.texcoords[mesh.indices[t * 3 + 1]], mesh.texcoords[mesh.indices[t * 3 + 2]], res,
        [&](int x, int y, glm::vec3) { ids[static_cast<size_t>(y) * res + x] = t; }, offset);
  return ids;
}

// Object-space point and normal where triangle t's texcoords equal the sample (x, y) + offset.
struct SurfacePoint {
  glm::vec3 position, normal;
};
SurfacePoint pointOnTriangle(const Mesh& mesh, uint32_t t, int res, int x, int y, glm::vec2 offset) {
  const uint32_t i0 = mesh.indices[t * 3], i1 = mesh.indices[t * 3 + 1], i2 = mesh.indices[t * 3 + 2];
  const glm::dvec2 s((x + offset.x) / res, 1.0 - (y + offset.y) / res);
  const glm::dvec2 a(mesh.texcoords[i0]), b(mesh.texcoords[i1]), c(mesh.texcoords[i2]);
  const glm::dvec2 e1 = b - a, e2 = c - a, d = s - a;
  const double det = e1.x * e2.y - e1.y * e2.x;
  const double w1 = (d.x * e2.y - d.y * e2.x) / det, w2 = (e1.x * d.y - e1.y * d.x) / det, w0 = 1.0 - w1 - w2;
  SurfacePoint p;
  p.position = glm::vec3(w0 * glm::dvec3(mesh.positions[i0]) + w1 * glm::dvec3(mesh.positions[i1]) + w2 * glm::dvec3(mesh.positions[i2]));
  const glm::vec3 face = glm::cross(mesh.positions[i1] - mesh.positions[i0], mesh.positions[i2] - mesh.positions[i0]);
  glm::vec3 n = mesh.normals.empty() ? face
                                     : glm::vec3(w0 * glm::dvec3(mesh.normals[i0]) + w1 * glm::dvec3(mesh.normals[i1]) +
                                                 w2 * glm::dvec3(mesh.normals[i2]));
  const float len = glm::length(n);
  p.normal = len > 0 && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0);
  return p;
}

// Fills texels of weight 0: `rings` rounds of averaging the covered 8-neighbours, then pull-push
// (each empty texel takes the average of the covered texels under its coarser ancestor).
void fillEmpty(std::vector<glm::vec4>& img, int size, int rings) {
  auto at = [&](int x, int y) -> glm::vec4& { return img[static_cast<size_t>(y) * size + x]; };
  for (int r = 0; r < rings; ++r) {
    std::vector<glm::vec4> next = img;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (at(x, y).w > 0) continue;
        glm::vec3 sum(0);
        float n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= size || yy >= size || at(xx, yy).w <= 0) continue;
            sum += glm::vec3(at(xx, yy));
            n += 1;
          }
        if (n > 0) next[static_cast<size_t>(y) * size + x] = glm::vec4(sum / n, 1.0f);
      }
    img.swap(next);
  }
  // Pull: a pyramid of averages of covered texels (w = whether any child was covered).
  std::vector<std::vector<glm::vec4>> levels;
  std::vector<int> sizes;
  levels.push_back(img);
  sizes.push_back(size);
  while (sizes.back() > 1) {
    const int s = sizes.back(), h = (s + 1) / 2;
    const std::vector<glm::vec4>& fine = levels.back();
    std::vector<glm::vec4> coarse(static_cast<size_t>(h) * h, glm::vec4(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < h; ++x) {
        glm::vec3 sum(0);
        float n = 0;
        for (int k = 0; k < 4; ++k) {
          const int xx = 2 * x + (k & 1), yy = 2 * y + (k >> 1);
          if (xx >= s || yy >= s) continue;
          const glm::vec4& v = fine[static_cast<size_t>(yy) * s + xx];
          if (v.w <= 0) continue;
          sum += glm::vec3(v);
          n += 1;
        }
        if (n > 0) coarse[static_cast<size_t>(y) * h + x] = glm::vec4(sum / n, 1.0f);
      }
    levels.push_back(std::move(coarse));
    sizes.push_back(h);
  }
  // Push: from the coarsest level down, empty texels take their parent's value.
  for (size_t l = levels.size() - 1; l-- > 0;) {
    const int s = sizes[l], h = sizes[l + 1];
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) {
        glm::vec4& v = levels[l][static_cast<size_t>(y) * s + x];
        if (v.w <= 0) v = levels[l + 1][static_cast<size_t>(y / 2) * h + x / 2];
      }
  }
  img = std::move(levels[0]);
}

ImageRGBA8 blankImage(int size) {
  ImageRGBA8 img;
  img.width = img.height = size;
  img.pixels.assign(static_cast<size_t>(size) * size * 4, 255);
  return img;
}

// Fixed ray directions: a Fibonacci spiral over the hemisphere, cosine-distributed (z up).
std::vector<glm::vec3> cosineDirections(int count) {
  std::vector<glm::vec3> dirs;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double r = std::sqrt((i + 0.5) / count), phi = golden * i;
    dirs.emplace_back(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                      static_cast<float>(std::sqrt(std::max(0.0, 1.0 - r * r))));
  }
  return dirs;
}

}  // namespace

TextureSet bakeTextureSet(const Mesh& mesh, const Material& material, const BakeOptions& options) {
  const int size = options.size, ss = std::max(1, options.supersample);
  TextureSet out;

  // 1. Base colour: ss x ss sub-samples per texel, each through the triangle covering it.
  std::vector<glm::vec4> colour(static_cast<size_t>(size) * size, glm::vec4(0));  // linear RGB sum, samples
  const int passes = ss * ss;
  std::optional<AlbedoSampler> albedo;
  for (int k = 0; k < passes; ++k) {
    const glm::vec2 offset((static_cast<float>(k % ss) + 0.5f) / ss, (static_cast<float>(k / ss) + 0.5f) / ss);
    const std::vector<uint32_t> ids = coverageIds(mesh, size, offset);
    if (!albedo) {  // made once the first pass says how many points there are (its grid may be worth baking)
      if (options.progress && !options.progress(0.0, "pattern")) throw BakeCancelled();
      const auto points = std::count_if(ids.begin(), ids.end(), [](uint32_t id) { return id != kEmpty; });
      albedo.emplace(material, static_cast<double>(points) * passes);
    }
    parallelRows(size, options, "base colour", 0.7 * k / passes, 0.7 * (k + 1) / passes, [&](int y) {
      for (int x = 0; x < size; ++x) {
        const size_t i = static_cast<size_t>(y) * size + x;
        if (ids[i] == kEmpty) continue;
        const SurfacePoint p = pointOnTriangle(mesh, ids[i], size, x, y, offset);
        colour[i] += glm::vec4((*albedo)(p.position, p.normal), 1.0f);
      }
    });
  }
  size_t covered = 0;
  for (glm::vec4& c : colour)
    if (c.w > 0) {
      c = glm::vec4(glm::vec3(c) / c.w, 1.0f);
      ++covered;
    }
  out.coverage = static_cast<double>(covered) / (static_cast<double>(size) * size);
  fillEmpty(colour, size, options.dilationTexels);
  out.baseColor = blankImage(size);
  for (size_t i = 0; i < colour.size(); ++i)
    for (int c = 0; c < 3; ++c) out.baseColor.pixels[i * 4 + c] = toByte(linearToSrgb(colour[i][c]));
  { std::vector<glm::vec4>().swap(colour); }

  // 2. Metallic-roughness: the material has one roughness and one metalness for the whole stone.
  out.metallicRoughness = blankImage(size);
  for (size_t i = 0; i < static_cast<size_t>(size) * size; ++i) {
    out.metallicRoughness.pixels[i * 4 + 1] = toByte(material.roughness);
    out.metallicRoughness.pixels[i * 4 + 2] = toByte(material.metalness);
  }

  // 3. Thickness at the texel centres of a smaller map.
  const int ts = options.thicknessSize > 0 ? options.thicknessSize : std::max(64, size / 4);
  const RayBvh bvh(mesh);
  const std::vector<glm::vec3> dirs = cosineDirections(std::max(1, options.thicknessRays));
  const std::vector<uint32_t> ids = coverageIds(mesh, ts, {0.5f, 0.5f});
  std::vector<float> thick(static_cast<size_t>(ts) * ts, -1.0f);
  const float maxT = 8.0f;  // the normalized mesh is 2 units across (diagonal 2 sqrt 3)
  parallelRows(ts, options, "thickness", 0.7, 0.98, [&](int y) {
    for (int x = 0; x < ts; ++x) {
      const size_t i = static_cast<size_t>(y) * ts + x;
      if (ids[i] == kEmpty) continue;
      const SurfacePoint p = pointOnTriangle(mesh, ids[i], ts, x, y, {0.5f, 0.5f});
      const glm::vec3 in = -p.normal;
      const glm::vec3 helper = std::abs(in.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
      const glm::vec3 t = glm::normalize(glm::cross(helper, in)), b = glm::cross(in, t);
      const glm::vec3 origin = p.position + in * 1e-4f;  // just below the surface: the point's own triangle is behind
      double sum = 0;
      int hits = 0;
      for (const glm::vec3& d : dirs) {
        const float h = bvh.nearestHit(origin, t * d.x + b * d.y + in * d.z, maxT);
        if (h < 0) continue;
        sum += h;
        ++hits;
      }
      thick[i] = hits > 0 ? static_cast<float>(sum / hits) : 0.0f;
    }
  });
  float largest = 0;
  for (float v : thick) largest = std::max(largest, v);
  out.thicknessScale = largest > 0 ? largest : 1.0f;
  std::vector<glm::vec4> thickImg(thick.size(), glm::vec4(0));
  for (size_t i = 0; i < thick.size(); ++i)
    if (thick[i] >= 0) thickImg[i] = glm::vec4(thick[i] / out.thicknessScale, 0, 0, 1);
  fillEmpty(thickImg, ts, options.dilationTexels);
  out.thickness = blankImage(ts);
  out.thicknessValues.resize(thickImg.size());
  for (size_t i = 0; i < thickImg.size(); ++i) {
    out.thicknessValues[i] = thickImg[i].x;
    out.thickness.pixels[i * 4] = out.thickness.pixels[i * 4 + 1] = out.thickness.pixels[i * 4 + 2] = toByte(thickImg[i].x);
  }
  if (options.progress) options.progress(1.0, "done");
  return out;
}

}  // namespace marble
