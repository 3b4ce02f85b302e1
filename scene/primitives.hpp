#pragma once
// Tessellated primitives in object space, faces wound counter-clockwise seen
// from outside, with per-vertex normals.
#include "scene/scene.hpp"

namespace mpr {

// Box and quad sides, and the plane, are `divisions` x `divisions` cells
// (more vertices for GL's per-vertex lighting), each side one polygon in
// Mesh::faces.
Mesh makeBox(int divisions = 1);                   // unit cube centred at the origin
Mesh makeSphere(int slices, int stacks);           // radius 1
Mesh makeCylinder(int slices);                     // radius 1, y from -0.5 to 0.5, capped
Mesh makeQuad(int divisions = 1);                  // unit square in the xy plane facing +z
Mesh makePlane(int divisions);                     // unit square in the xz plane facing +y, subdivided

// Applies a world transform to positions and (inverse-transpose) normals.
void transformMesh(Mesh& mesh, const Mat4& m);

}  // namespace mpr
