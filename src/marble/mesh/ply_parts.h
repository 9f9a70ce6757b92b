#pragma once
// A PLY body's vertex and face elements read in parts over threads (ply_loader.cpp's fast path).
// Each reader handles the common layouts only -- binary: fixed-size vertices, faces of one list
// length throughout; ASCII: one element per line -- and returns false, with the read position
// and `indices` as they were, at anything else: a list of another length, a line holding more or
// less than one element, a number it cannot read, an index out of range, a NaN, too little data,
// a limit. The caller then reads the element front to back, which finds the problem and gives its
// message (file, place, problem), so messages do not depend on the part count.
#include <cstdint>
#include <string_view>
#include <vector>

#include "marble/mesh/mesh_internal.h"
#include "marble/mesh/ply_format.h"

namespace marble::mesh_detail::ply {

// `body`: the data from `pos` (the element's first byte) on; `pos` is moved past the element.
// The mesh's arrays are sized for the element already.
bool readBinaryVerticesInParts(std::string_view body, const Element& e, const VertexLayout& layout, bool swap, Mesh& mesh,
                               unsigned parts, size_t& pos);
// Appends the triangles (polygons as fans) of the face element to `indices`; `list` is the
// vertex_indices property.
bool readBinaryFacesInParts(std::string_view body, const Element& e, size_t list, uint64_t vertexCount, bool swap,
                            std::vector<uint32_t>& indices, unsigned parts, size_t& pos);

// ASCII: `text` at the element (after the previous one's last value); moved past it with its line
// count kept.
bool readAsciiVerticesInParts(TextCursor& text, const Element& e, const VertexLayout& layout, Mesh& mesh, unsigned parts);
bool readAsciiFacesInParts(TextCursor& text, const Element& e, size_t list, uint64_t vertexCount,
                           std::vector<uint32_t>& indices, unsigned parts);

}  // namespace marble::mesh_detail::ply
