#pragma once
// A triangle corner's angle, atan2(|e1 x e2|, e1 . e2) in double rounded to float, as the crease
// normals weight by it (vertex_normals.cpp) -- bit for bit what std::atan2 gives, at about a third
// of its cost: libm's atan2 was 12 % of a 1.6 M-triangle OBJ's whole load (three per triangle).
#include <optional>

namespace marble::mesh_detail {

// atan2(y, x) for y > 0 and finite x, y by a table of 33 arctangents (std::atan at k / 32) and a
// five-term series on the remainder (|t| <= 1/64: the series' error is below 2^-66), within a
// few double ulps; rounded to float only when every value within 2^-40 (relative) of it rounds
// to the same float. libm's atan2 is within 1 ulp of the true value, so it rounds to that float
// too. Otherwise (about 3 in 100,000 angles, and y <= 0, x or y not finite) nullopt.
std::optional<float> fastCornerAngle(double y, double x);

// (float)std::atan2(y, x), bit for bit: the fast path where it is safe, else std::atan2.
float cornerAngle(double y, double x);

}  // namespace marble::mesh_detail
