#pragma once
// Whether a mesh bounds a solid, and which way its triangles are wound: what lets the camera's
// pass skip the faces turned away from it (render/face_culling.h). For a closed surface, every
// edge used by as many triangles one way as the other (two wound against each other, or four
// where parts touch), the winding number about any point not on the surface is defined; it is 0 outside the mesh's bounding box, and crossing a triangle
// changes it by one, up where the triangle's winding normal points against the crossing ray. A
// ray from an eye outside the box therefore first crosses a triangle whose normal faces the eye
// when every part's triangles point out of it (Outward), and one whose normal faces away when
// every part's point in (Inward). A surface with a boundary (the bunny's holes, the teapot's
// open spout and lid) shows either side.
#include "marble/mesh/mesh.h"

namespace marble {

enum class SurfaceWinding {
  Open,     // an edge used more often one way than the other (a boundary, triangles wound alike),
            // or parts wound different ways (triangles with two corners at one point, which cover
            // nothing, are left out)
  Outward,  // closed; every connected part encloses a positive volume (counter-clockwise seen from outside)
  Inward,   // closed; every part encloses a negative volume
};

// Corners at the same position (bit for bit, point_ids.h) are one point, whatever the vertex:
// crease normals split vertices, not the surface.
SurfaceWinding closedSurfaceWinding(const Mesh& mesh);

// A simplifier can flatten a small detached part into a sliver wound the other way (the dragon's
// light proxy: 20 triangles of volume -8.75e-9, 0.017 x 0.004 x 0.005 units, beside its main part's 0.444),
// and a part wound against the rest makes the surface Open. Each connected part whose signed
// volume has the other sign than the largest part's, and at most kSliverVolumeFraction of its
// magnitude, has its triangles' winding reversed (the positions and normals stay): what the light
// and the camera meet first, drawn with both faces, is the same either way (no depth test or
// shader of a both-faced draw reads the winding but the geometry pass's gl_FrontFacing, which
// then keeps the sliver's normal as stored on its side toward the eye), and the copy can be
// culled. (Accepting such parts in closedSurfaceWinding instead would not be: culled, a ray
// entering the sliver through its turned-away face would first meet a face past it, up to the
// part's extent further -- along a grazing ray, the sheet's 0.017 units -- whatever its volume.)
// Returns how many parts were turned.
constexpr double kSliverVolumeFraction = 1e-6;  // a cube 1 % of the part's size
size_t orientSlivers(Mesh& mesh);

}  // namespace marble
