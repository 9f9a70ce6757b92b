#include "marble/mesh/weld_corners.h"

namespace marble::mesh_detail {

Welder::Welder(size_t expectedVertices) {
  size_t capacity = 16;
  while (capacity < expectedVertices * 2) capacity *= 2;
  slots_.assign(capacity, kEmpty);
  mask_ = capacity - 1;
}

size_t Welder::slotFor(const glm::vec3& p) const {
  size_t slot = hashOf(p) & mask_;
  while (slots_[slot] != kEmpty) slot = (slot + 1) & mask_;
  return slot;
}

void Welder::grow(const std::vector<glm::vec3>& positions) {
  slots_.assign(slots_.size() * 2, kEmpty);
  mask_ = slots_.size() - 1;
  for (uint32_t i = 0; i < positions.size(); ++i) slots_[slotFor(positions[i])] = i;
}

WeldedCorners weldCorners(const std::vector<glm::vec3>& corners) {
  WeldedCorners out;
  out.indices.resize(corners.size());
  Welder welder(corners.size() / 6);  // a closed triangle mesh: ≈ 6 corners per vertex
  for (size_t c = 0; c < corners.size(); ++c) out.indices[c] = welder.add(corners[c], out.positions);
  return out;
}

}  // namespace marble::mesh_detail
