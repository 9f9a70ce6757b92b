// Meshes generated in code. All are closed, wound counter-clockwise seen from outside (positive
// signed volume), normalized (bounding-box centre at the origin, largest extent 2.0) and carry
// one unit normal per vertex.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/vertex_normals.h"

namespace marble {
namespace {

constexpr double kPi = std::numbers::pi;

// Makes the winding outward if it came out inward, then normalizes; computes angle-weighted normals
// (default crease angle) when the generator supplied none.
Mesh finish(Mesh mesh, const std::string& name) {
  if (signedVolume(mesh) < 0.0)
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  normalizeMesh(mesh, "builtin:" + name);
  if (mesh.normals.empty()) computeVertexNormals(mesh, kDefaultCreaseAngleDeg);
  return mesh;
}

// A quad a-b-c-d, counter-clockwise seen from outside, as two triangles with its own four
// vertices and a flat normal.
void addFlatQuad(Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  for (const glm::vec3& p : {a, b, c, d}) {
    m.positions.push_back(p);
    m.normals.push_back(n);
  }
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// Quads between `rings` closed rings of `segments` vertices each (ring i+1 after ring i, both
// closed around). Vertex (i, j) is at i * segments + j.
void addTubeIndices(Mesh& m, uint32_t rings, uint32_t segments, bool closeRings) {
  const uint32_t ringCount = closeRings ? rings : rings - 1;
  for (uint32_t i = 0; i < ringCount; ++i) {
    const uint32_t i1 = (i + 1) % rings;
    for (uint32_t j = 0; j < segments; ++j) {
      const uint32_t j1 = (j + 1) % segments;
      const uint32_t a = i * segments + j, b = i1 * segments + j, c = i1 * segments + j1, d = i * segments + j1;
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  }
}

// "sculpture": a trefoil knot tube whose radius swells and thins three times around the knot
// (radius 0.18 to 0.50 against a knot about 5.5 across, before normalization), so the same
// object has thin parts that glow when back-lit and thick parts that stay dark. 320 x 40
// segments: 12,800 vertices, 25,600 triangles. The knot lies in the XY plane, facing +Z.
Mesh makeSculpture() {
  constexpr uint32_t kAlong = 320, kAround = 40;
  auto curve = [](double t) {
    return glm::dvec3(std::sin(t) + 2.0 * std::sin(2.0 * t), std::cos(t) - 2.0 * std::cos(2.0 * t), -std::sin(3.0 * t));
  };
  auto d1 = [](double t) {
    return glm::dvec3(std::cos(t) + 4.0 * std::cos(2.0 * t), -std::sin(t) + 4.0 * std::sin(2.0 * t), -3.0 * std::cos(3.0 * t));
  };
  auto d2 = [](double t) {
    return glm::dvec3(-std::sin(t) - 8.0 * std::sin(2.0 * t), -std::cos(t) + 8.0 * std::cos(2.0 * t), 9.0 * std::sin(3.0 * t));
  };
  Mesh m;
  m.positions.reserve(kAlong * kAround);
  for (uint32_t i = 0; i < kAlong; ++i) {
    const double t = 2.0 * kPi * i / kAlong;
    // Frenet frame: this knot's curvature never vanishes, so the frame is smooth and periodic
    // (no seam where the tube closes).
    const glm::dvec3 tangent = glm::normalize(d1(t));
    const glm::dvec3 binormal = glm::normalize(glm::cross(d1(t), d2(t)));
    const glm::dvec3 normal = glm::cross(binormal, tangent);
    const double radius = 0.34 + 0.16 * std::sin(3.0 * t);
    for (uint32_t j = 0; j < kAround; ++j) {
      const double a = 2.0 * kPi * j / kAround;
      m.positions.push_back(glm::vec3(curve(t) + radius * (std::cos(a) * normal + std::sin(a) * binormal)));
    }
  }
  addTubeIndices(m, kAlong, kAround, true);
  return finish(std::move(m), "sculpture");  // smooth normals: the radius varies, so not radial
}

// "sphere": an icosahedron subdivided four times (2,562 vertices, 5,120 triangles), radius 1.
Mesh makeSphere() {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  for (glm::dvec3 p : {glm::dvec3(-1, g, 0), glm::dvec3(1, g, 0), glm::dvec3(-1, -g, 0), glm::dvec3(1, -g, 0),
                       glm::dvec3(0, -1, g), glm::dvec3(0, 1, g), glm::dvec3(0, -1, -g), glm::dvec3(0, 1, -g),
                       glm::dvec3(g, 0, -1), glm::dvec3(g, 0, 1), glm::dvec3(-g, 0, -1), glm::dvec3(-g, 0, 1)})
    m.positions.push_back(glm::vec3(glm::normalize(p)));
  m.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
               3, 9,  4,  3, 4,  2, 3, 2, 6, 3, 6,  8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
  for (int level = 0; level < 4; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, static_cast<uint32_t>(m.positions.size()));
      if (inserted) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<uint32_t> next;
    next.reserve(m.indices.size() * 4);
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.indices = std::move(next);
  }
  m.normals = m.positions;  // unit sphere: the normal is the position
  return finish(std::move(m), "sphere");
}

// "cube": [-1, 1]^3, 24 vertices (four per face), flat normals.
Mesh makeCube() {
  Mesh m;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      const glm::vec3 n = axes[axis] * sign;
      const glm::vec3 u = axes[(axis + 1) % 3] * sign;
      const glm::vec3 v = glm::cross(n, u);  // u x v = n: counter-clockwise seen from outside
      addFlatQuad(m, n - u - v, n + u - v, n + u + v, n - u + v);
    }
  return finish(std::move(m), "cube");
}

// "slab": a wedge for subsurface tests. Exact geometry (already normalized, so it is as stated):
//   x in [-1, 1], y in [-0.75, 0.75], and thickness along z growing linearly with x,
//   z in [-h(x), +h(x)] with h(x) = (0.55 + 0.45 x) / 2, i.e. 0.1 thick at x = -1 and 1.0 thick
//   at x = +1. Front (+z) and back (-z) faces are planes tilted symmetrically; 24 vertices,
//   12 triangles, flat normals.
Mesh makeSlab() {
  auto h = [](float x) { return (0.55f + 0.45f * x) / 2.0f; };
  const float y0 = -0.75f, y1 = 0.75f;
  const glm::vec3 A(-1, y0, h(-1)), B(1, y0, h(1)), C(1, y1, h(1)), D(-1, y1, h(-1));     // front
  const glm::vec3 E(-1, y0, -h(-1)), F(1, y0, -h(1)), G(1, y1, -h(1)), H(-1, y1, -h(-1));  // back
  Mesh m;
  addFlatQuad(m, A, B, C, D);  // front
  addFlatQuad(m, F, E, H, G);  // back
  addFlatQuad(m, B, F, G, C);  // +x (thick end)
  addFlatQuad(m, E, A, D, H);  // -x (thin end)
  addFlatQuad(m, D, C, G, H);  // top
  addFlatQuad(m, E, F, B, A);  // bottom
  return finish(std::move(m), "slab");
}

// "torus": ring radius 1, tube radius 0.4, lying in the XZ plane (axis +Y); 96 x 48 segments,
// 4,608 vertices, 9,216 triangles. After normalization the ring radius is 1/1.4.
Mesh makeTorus() {
  constexpr uint32_t kRing = 96, kTube = 48;
  constexpr double R = 1.0, r = 0.4;
  Mesh m;
  for (uint32_t i = 0; i < kRing; ++i) {
    const double u = 2.0 * kPi * i / kRing;
    for (uint32_t j = 0; j < kTube; ++j) {
      const double v = 2.0 * kPi * j / kTube;
      const glm::dvec3 n(std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u));
      const glm::dvec3 centre(R * std::cos(u), 0.0, R * std::sin(u));
      m.positions.push_back(glm::vec3(centre + r * n));
      m.normals.push_back(glm::vec3(n));
    }
  }
  addTubeIndices(m, kRing, kTube, true);
  return finish(std::move(m), "torus");
}

struct Builtin {
  std::string_view name;
  Mesh (*make)();
};

constexpr Builtin kBuiltins[] = {
    {"sculpture", makeSculpture}, {"sphere", makeSphere}, {"cube", makeCube}, {"slab", makeSlab}, {"torus", makeTorus},
};

}  // namespace

std::vector<std::string> builtinMeshNames() {
  std::vector<std::string> names;
  for (const Builtin& b : kBuiltins) names.emplace_back(b.name);
  return names;
}

Mesh builtinMesh(std::string_view name) {
  for (const Builtin& b : kBuiltins)
    if (b.name == name) return b.make();
  std::string known;
  for (const Builtin& b : kBuiltins) known += (known.empty() ? "" : ", ") + std::string(b.name);
  throw InputError("builtin:" + std::string(name), "", "unknown built-in mesh; known: " + known);
}

}  // namespace marble
