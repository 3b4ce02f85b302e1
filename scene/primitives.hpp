#pragma once
// Tessellated primitives in object space, faces wound counter-clockwise seen
// from outside, with per-vertex normals.
#include "scene/scene.hpp"

namespace mpr {

Mesh makeBox();                                    // unit cube centred at the origin
Mesh makeSphere(int slices, int stacks);           // radius 1
Mesh makeCylinder(int slices);                     // radius 1, y from -0.5 to 0.5, capped
Mesh makeQuad();                                   // unit square in the xy plane facing +z
Mesh makePlane(int divisions);                     // unit square in the xz plane facing +y, subdivided

// Applies a world transform to positions and (inverse-transpose) normals.
void transformMesh(Mesh& mesh, const Mat4& m);

}  // namespace mpr
