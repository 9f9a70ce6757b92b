#pragma once
// `marble texture` for the vein models (issue 16): marble.png as a planar slice of the solid
// pattern -- what a mesh cut by that plane shows -- and `--tile` for a seamless tile. Only
// parsing and pixels here; cmd_texture.cpp writes the files.
#include <string>

#include "marble/core/image.h"
#include "marble/scene/material.h"

namespace marble {

// The plane `axis = offset` (object space; the mesh is normalized into [-1,1]^3), seen as the
// square [-1,1]^2 of the other two axes: normal z shows (x right, y up), normal y (x right,
// z down: the top face seen from above), normal x (z right, y up).
struct SliceSpec {
  int axis = 2;         // 0 x, 1 y, 2 z
  float offset = 0.0f;  // object units, [-1e3, 1e3]
};
// "z=0.25", "x=-0.5", "y=0": throws InputError("--slice", text, problem).
SliceSpec parseSlice(const std::string& text);

// The object-space point of slice coordinates (s, t) in [0,1]^2, (0,0) the top-left corner.
glm::vec3 slicePoint(const SliceSpec& slice, float s, float t);

struct SliceImages {
  ImageRGBA8 marble;  // colour, sRGB-encoded
  ImageRGBA8 veins;   // the value before colour (0 = a vein's heart), grey
};
// size x size pixels, pixel centres at s = (x + 0.5) / size. With `tile`, a band of
// kTileBand of the width at the right and bottom edges cross-fades into the copy of the slab
// one slice-width on (the solid pattern two units further), so the right edge continues into
// the left and the bottom into the top: the tile repeats without a seam. Rows run on all cores.
inline constexpr float kTileBand = 0.15f;
SliceImages renderVeinSlice(const Material& m, const SliceSpec& slice, int size, bool tile);

}  // namespace marble
