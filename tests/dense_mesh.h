#pragma once
// A built-in mesh made dense for the tests of simplified copies (the suite must not need the
// scans in ../shared/models): every triangle split into four at its edge midpoints, then one
// Laplacian smoothing step, so the new triangles are not coplanar with the old ones and a
// simplifier has real curvature to keep (a bare midpoint split could be undone with no error).
#include <map>
#include <utility>

#include "marble/mesh/mesh.h"
#include "marble/mesh/vertex_normals.h"

namespace marble::test {

inline Mesh subdividedSmoothed(Mesh m, int levels) {
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
      auto [it, added] = midpoint.try_emplace(key, static_cast<uint32_t>(m.positions.size()));
      if (added) m.positions.push_back(0.5f * (m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<uint32_t> out;
    out.reserve(m.indices.size() * 4);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      out.insert(out.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    m.indices = std::move(out);
    // One smoothing step: each vertex halfway to the mean of its edge neighbours.
    std::vector<glm::vec3> sum(m.positions.size(), glm::vec3(0.0f));
    std::vector<float> count(m.positions.size(), 0.0f);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
      for (int e = 0; e < 3; ++e) {
        const uint32_t a = m.indices[t + e], b = m.indices[t + (e + 1) % 3];
        sum[a] += m.positions[b];
        sum[b] += m.positions[a];
        count[a] += 1.0f;
        count[b] += 1.0f;
      }
    for (size_t i = 0; i < m.positions.size(); ++i)
      if (count[i] > 0.0f) m.positions[i] = 0.5f * m.positions[i] + 0.5f * sum[i] / count[i];
  }
  m.normals.clear();
  m.texcoords.clear();
  normalizeMesh(m);
  computeVertexNormals(m, kNoCreaseDeg);  // smooth everywhere, as a scan is
  return m;
}

}  // namespace marble::test
