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

}  // namespace marble
