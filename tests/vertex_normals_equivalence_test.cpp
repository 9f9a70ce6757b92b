// computeVertexNormals (corners filed by point, fans found point by point over threads, corner
// angles by a series) equals the first, sort-based implementation (vertex_normals_reference.h):
// positions, indices and texture coordinates bit for bit, normals within kNormalTolerance per
// component (the angles differ from libm's atan2 by at most one float ulp, corner_angle.h; the sums
// run in the same order), on meshes that exercise every rule (shared positions, +0 and -0, creases,
// edges with 1 or 3+ triangles, flipped winding, bow-ties, degenerate triangles, points with
// hundreds and with 70,000 edges).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "marble/mesh/corner_angle.h"

#include "marble/mesh/vertex_normals.h"
#include "vertex_normals_reference.h"

namespace marble {
namespace {

// Per component: a unit normal's float rounding is ~6e-8; an angle one ulp off moves a sum of a
// few terms by about as much.
constexpr float kNormalTolerance = 1e-6f;

// The same topology bit for bit (positions, texture coordinates, indices: which vertices are
// copied, in which order) and normals within `tolerance` per component.
bool sameWithin(const Mesh& a, const Mesh& b, float tolerance = kNormalTolerance) {
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  if (!same(a.positions, b.positions) || !same(a.texcoords, b.texcoords) || a.indices != b.indices ||
      a.normals.size() != b.normals.size())
    return false;
  for (size_t i = 0; i < a.normals.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(a.normals[i][k] - b.normals[i][k]) <= tolerance)) return false;
  return true;
}

// A soup on a coarse lattice: many triangles share positions through different vertex indices, edges
// have 1-5 triangles in either direction, some triangles are degenerate, half the zeros are -0.
Mesh latticeSoup(unsigned seed, size_t vertices, size_t triangles) {
  std::mt19937 rng(seed);
  Mesh m;
  for (size_t i = 0; i < vertices; ++i) {
    const float z = static_cast<float>(rng() % 3) * 0.5f;
    m.positions.emplace_back(static_cast<float>(rng() % 7) * 0.5f - 1.5f, static_cast<float>(rng() % 5) * 0.5f,
                             (i % 2 && z == 0.0f) ? -0.0f : z);
    m.texcoords.emplace_back(static_cast<float>(i) / static_cast<float>(vertices), 0.5f);
  }
  for (size_t t = 0; t < 3 * triangles; ++t) m.indices.push_back(static_cast<uint32_t>(rng() % vertices));
  return m;
}

// A folded grid (heights at random, so some edges are creases) with a few hundred of its triangles
// repeated, some flipped: edges with 3 triangles and opposite windings at points of ~6-12 corners,
// the point pass's small path (the lattice soups' points have hundreds of corners).
Mesh foldedGridWithExtras(unsigned seed) {
  std::mt19937 rng(seed);
  Mesh m;
  const int n = 40;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.positions.emplace_back(x * 0.1f, y * 0.1f, static_cast<float>(rng() % 3) * 0.06f);
  auto at = [&](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      m.indices.insert(m.indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y), at(x + 1, y + 1), at(x, y + 1)});
  const size_t triangles = m.indices.size() / 3;
  for (int i = 0; i < 300; ++i) {
    const size_t t = rng() % triangles;
    uint32_t v[3] = {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
    if (i % 2) std::swap(v[1], v[2]);
    m.indices.insert(m.indices.end(), v, v + 3);
  }
  return m;
}

// One point at the centre of a 400-triangle fan (its bucket is sorted by std::sort, not by the
// insertion sort the small buckets get), every other spoke folded by 70 degrees.
Mesh foldedFan() {
  Mesh m;
  m.positions.emplace_back(0.0f, 0.0f, 0.0f);
  const int spokes = 400;
  for (int i = 0; i < spokes; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / spokes;
    m.positions.emplace_back(std::cos(a), std::sin(a), i % 2 ? 0.0f : 1.4f);
  }
  for (int i = 0; i < spokes; ++i) m.indices.insert(m.indices.end(), {0u, 1u + i, 1u + (i + 1) % spokes});
  return m;
}

void expectSameAsReference(const Mesh& input, float crease, const char* what) {
  Mesh fast = input, reference = input;
  computeVertexNormals(fast, crease);
  reference::computeVertexNormalsBySorting(reference, crease);
  EXPECT_TRUE(sameWithin(fast, reference)) << what << ", crease " << crease;
}

TEST(VertexNormalsEquivalence, BuiltinMeshesEqualTheSortedReference) {
  for (const std::string& name : builtinMeshNames()) {
    Mesh m = builtinMesh(name);
    m.normals.clear();
    for (float crease : {kDefaultCreaseAngleDeg, 30.0f, kNoCreaseDeg}) expectSameAsReference(m, crease, name.c_str());
  }
}

TEST(VertexNormalsEquivalence, SoupsAndFansEqualTheSortedReference) {
  for (unsigned seed : {1u, 2u, 3u})
    for (float crease : {kDefaultCreaseAngleDeg, 10.0f, kNoCreaseDeg})
      expectSameAsReference(latticeSoup(seed, 3000, 20000), crease, "lattice soup");
  for (float crease : {kDefaultCreaseAngleDeg, 80.0f, kNoCreaseDeg}) expectSameAsReference(foldedFan(), crease, "folded fan");
  for (unsigned seed : {1u, 2u})
    for (float crease : {kDefaultCreaseAngleDeg, 20.0f, kNoCreaseDeg})
      expectSameAsReference(foldedGridWithExtras(seed), crease, "folded grid with extras");
  // Only degenerate triangles: no edge is used at all (found by fuzz_obj under UBSan: an empty
  // bucket array's null data() must not be offset).
  Mesh degenerate;
  degenerate.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}};
  degenerate.indices = {0, 1, 0, 2, 2, 1};
  for (float crease : {kDefaultCreaseAngleDeg, kNoCreaseDeg}) expectSameAsReference(degenerate, crease, "degenerate only");
  // A point whose first corner (in file order) is on a zero-area triangle with three distinct
  // points (collinear): filed under the point but taking no part, so the fan's first corner is
  // the next one (the no-crease path picks it explicitly).
  Mesh collinear;
  collinear.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  collinear.indices = {0, 1, 2, 0, 1, 3, 0, 3, 4, 0, 4, 1};
  for (float crease : {kDefaultCreaseAngleDeg, kNoCreaseDeg}) expectSameAsReference(collinear, crease, "collinear first");
}

// Large enough (150,000 triangles) that the triangles and the points are split over threads (two
// or more parts on a machine with two or more cores).
TEST(VertexNormalsEquivalence, ThreadedMeshEqualsTheSortedReference) {
  expectSameAsReference(latticeSoup(7, 40000, 150000), kDefaultCreaseAngleDeg, "150k-triangle soup");
}

// Negative control: the comparison sees a different crease angle's result (it can fail).
TEST(VertexNormalsEquivalence, ComparisonDetectsADifferentCrease) {
  Mesh input = builtinMesh("cube");
  input.normals.clear();
  Mesh a = input, b = input;
  computeVertexNormals(a, kDefaultCreaseAngleDeg);
  reference::computeVertexNormalsBySorting(b, kNoCreaseDeg);
  EXPECT_FALSE(sameWithin(a, b));
}

// Negative control for the tolerance: one normal moved by 1e-5 (ten times the tolerance) in one
// component is seen.
TEST(VertexNormalsEquivalence, ComparisonDetectsANormalOffByTenTolerances) {
  Mesh input = latticeSoup(4, 300, 2000);
  Mesh a = input, b = input;
  computeVertexNormals(a, kDefaultCreaseAngleDeg);
  reference::computeVertexNormalsBySorting(b, kDefaultCreaseAngleDeg);
  ASSERT_TRUE(sameWithin(a, b));
  a.normals[a.normals.size() / 2].y += 10.0f * kNormalTolerance;
  EXPECT_FALSE(sameWithin(a, b));
}

// Two closed fans that meet only at their apex (a bow-tie of two pyramids tip to tip): every edge at
// the apex is smooth and manifold, yet the apex has two fans and its vertex is copied once. With
// all six triangles' corners at one vertex and one point.
Mesh bowTie() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 1, -1}, {-1, 1, -1}, {0, -1, -1}, {1, 1, 1}, {-1, 1, 1}, {0, -1, 1}};
  // Pyramid below (apex 0, base 1 2 3) and above (apex 0, base 4 5 6), each closed by its base.
  m.indices = {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2, 0, 5, 4, 0, 6, 5, 0, 4, 6, 4, 5, 6};
  return m;
}

TEST(VertexNormalsEquivalence, BowTieEqualsTheSortedReference) {
  Mesh m = bowTie();
  for (float crease : {kDefaultCreaseAngleDeg, 80.0f, 179.0f, kNoCreaseDeg}) expectSameAsReference(m, crease, "bow-tie");
  Mesh two = m;
  computeVertexNormals(two, 179.0f);
  EXPECT_EQ(two.positions.size(), m.positions.size() + 1) << "the apex spans two fans";
  // A third triangle on one base edge makes it non-manifold (hard), and a repeated one a doubled edge.
  m.indices.insert(m.indices.end(), {1u, 2u, 5u, 0u, 1u, 2u});
  for (float crease : {kDefaultCreaseAngleDeg, 179.0f, kNoCreaseDeg}) expectSameAsReference(m, crease, "bow-tie, non-manifold");
}

// A point with 70,000 corners (more than the point pass's 16-bit local keys hold): its vertices are
// settled by the wide path.
TEST(VertexNormalsEquivalence, PointWithSeventyThousandCornersEqualsTheSortedReference) {
  Mesh m;
  m.positions.emplace_back(0.0f, 0.0f, 0.0f);
  const int spokes = 70000;
  for (int i = 0; i < spokes; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / spokes;
    m.positions.emplace_back(std::cos(a), std::sin(a), static_cast<float>(i % 3) * 0.001f);
  }
  for (int i = 0; i < spokes; ++i) m.indices.insert(m.indices.end(), {0u, 1u + i, 1u + (i + 1) % spokes});
  // Every seventh triangle upside down: its edges are hard, so the centre has thousands of fans.
  for (int i = 0; i < spokes; i += 7) std::swap(m.indices[3 * i + 1], m.indices[3 * i + 2]);
  expectSameAsReference(m, kDefaultCreaseAngleDeg, "70,000 spokes");
}

// The series angle against libm's atan2, as the reference computes it: equal as floats or one ulp
// apart, and within 3e-9 rad in double (the series' bound, corner_angle.h), over random corners
// from needles to nearly flat ones, and the special cases.
TEST(VertexNormalsTolerance, CornerAngleMatchesLibm) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-12, 3);
  int oneUlp = 0;
  for (int i = 0; i < 200000; ++i) {
    const glm::dvec3 p0(u(rng), u(rng), u(rng));
    const glm::dvec3 p1 = p0 + std::ldexp(1.0, scale(rng)) * glm::dvec3(u(rng), u(rng), u(rng));
    const glm::dvec3 p2 = p0 + std::ldexp(1.0, scale(rng)) * glm::dvec3(u(rng), u(rng), u(rng));
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
    const double y = glm::length(glm::cross(e1, e2)), x = glm::dot(e1, e2);
    const double exact = std::atan2(y, x);
    ASSERT_NEAR(atan2OfLength(y, x), exact, 3e-9) << y << " " << x;
    const float ours = cornerAngleOf(p0, p1, p2), libm = static_cast<float>(exact);
    ASSERT_LE(std::fabs(ours - libm), std::nextafter(libm, 10.0f) - libm) << y << " " << x;
    oneUlp += ours != libm;
  }
  EXPECT_LT(oneUlp, 2000) << "rounding apart should be rare";
  EXPECT_EQ(atan2OfLength(0.0, 0.0), 0.0);
  EXPECT_EQ(atan2OfLength(0.0, -1.0), std::numbers::pi);
  EXPECT_EQ(atan2OfLength(0.0, 2.0), 0.0);
  EXPECT_NEAR(atan2OfLength(1.0, 0.0), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(atan2OfLength(1.0, -1.0), 3 * std::numbers::pi / 4, 1e-15);
}

}  // namespace
}  // namespace marble
