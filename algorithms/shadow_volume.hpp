#pragma once
// Shadow volume geometry for one object and one point light (Heidmann's
// in-out counting, as the 1994 paper uses it), and the geometric
// predicates the drawwindow recursion needs around it. No GL here: the
// caller draws what these functions return.
//
// The volume is a closed surface, every face counter-clockwise seen from
// outside (so in z-pass counting front faces increment and back faces
// decrement):
//  - light cap: the lit triangles exactly as the mesh has them (same
//    positions, same vertex order, so they rasterise to the same depths as
//    the object itself);
//  - sides: one quad a, b, b', a' per silhouette edge (silhouette.hpp);
//  - dark cap: the LIT triangles again, extruded, with reversed winding.
//    Chosen over the extruded unlit triangles because its boundary is the
//    silhouette by construction: the surface is closed even for an open
//    caster (the extruded unlit set of an open mesh does not match its
//    silhouette), and it uses exactly the extruded points of the sides.
// Extrusion: v' = light + R normalize(v - light), i.e. v moved by
// t = R - |v - light| away from the light, with one R for the whole volume,
// chosen so that every point of the dark cap (not only its corners: a flat
// cap triangle between far corners can dip back towards the light) lies
// outside the receivers' bounding sphere. So every receiver point behind
// the caster, as seen from the light, is inside the volume. The sphere
// should enclose the caster too (sceneBoundingSphere does), so that it
// shadows its own far side consistently.
#include <array>
#include <cstdint>
#include <vector>

#include "algorithms/plane.hpp"
#include "algorithms/silhouette.hpp"
#include "scene/scene.hpp"

namespace mpr {

using VolumeTriangle = std::array<Vec3, 3>;

struct ShadowVolume {
  Vec3 light{0.0f};
  std::vector<std::array<Vec3, 4>> sides;  // a, b, b', a' (planar up to float rounding)
  std::vector<VolumeTriangle> lightCap;    // the lit triangles, as the mesh has them
  std::vector<VolumeTriangle> darkCap;     // the lit triangles extruded, reversed
  double extrusionRadius = 0.0;            // R: every extruded point is this far from the light
  bool casterClosed = false;               // the caster mesh is closed (else: warn, see silhouette.hpp)
  std::size_t casterBoundaryEdges = 0;

  bool empty() const { return lightCap.empty(); }
  // Every face as triangles: light cap, sides (a, b, b' and a, b', a'),
  // dark cap; all counter-clockwise seen from outside.
  std::vector<VolumeTriangle> triangles() const;
};

// The extrusion radius for the lit triangles of `mesh`: the smallest R
// (plus a 0.1% margin) with every dark-cap point outside `receivers` and
// every extruded point beyond its original. The bound uses each cap
// triangle's plane distance from the light; if a lit triangle's plane
// passes within 1e-6 (relative) of the light, R is capped at 1e6 times the
// receivers' reach and the guarantee is lost (the light would have to sit
// almost on a lit face). 0 when nothing is lit.
double shadowExtrusionRadius(const Mesh& mesh, const std::vector<std::uint32_t>& litTriangles, Vec3 light,
                             const BoundingSphere& receivers);

// v moved away from the light to distance R from it (double, rounded once
// to float: equal inputs give bit-equal outputs, which keeps the volume
// watertight).
Vec3 extrudeFromLight(Vec3 v, Vec3 light, double R);

ShadowVolume buildShadowVolume(const Mesh& mesh, const Silhouette& silhouette, Vec3 light,
                               const BoundingSphere& receivers);
// Convenience: connectivity and silhouette computed here.
ShadowVolume buildShadowVolume(const Mesh& mesh, Vec3 light, const BoundingSphere& receivers);

// A sphere around the points (centre of their bounding box), and around
// every object of a scene.
BoundingSphere boundingSphereOf(const std::vector<Vec3>& points);
BoundingSphere sceneBoundingSphere(const Scene& scene);

// The winding number of the volume's surface about p (double, by solid
// angles): 1 inside, 0 outside, for any closed outward-oriented surface.
double shadowVolumeWinding(const ShadowVolume& volume, Vec3 p);
// Inside when the winding number exceeds one half. Points within rounding
// of the surface may go either way.
bool pointInsideShadowVolume(const ShadowVolume& volume, Vec3 p);

// Conservative triangle-triangle contact in double (separating axes with a
// relative tolerance of 1e-9): never false when the triangles share a
// point; may be true when they miss by less than the tolerance.
bool trianglesMayIntersect(const std::array<DVec3, 3>& t, const std::array<DVec3, 3>& u);

// The four world-space corners of the near clip rectangle of a
// gluLookAt(eye, lookAt, up) * gluPerspective(fovY, aspect, zNear, ...)
// camera: bottom-left, bottom-right, top-right, top-left as the camera sees
// them (counter-clockwise seen from the eye). `up` parallel to the view
// direction (a singular gluLookAt) uses some perpendicular instead of NaN.
std::array<Vec3, 4> nearPlaneCorners(Vec3 eye, Vec3 lookAt, Vec3 up, double fovYDegrees, double aspect,
                                     double zNear);
std::array<Vec3, 4> nearPlaneCorners(const Camera& camera, double aspect);

// True when z-pass counting could be wrong for some pixel: the volume meets
// the near clip rectangle (every pixel's count starts there). Tested: the
// eye or a corner inside the volume (the rectangle wholly inside), or any
// volume face touching either half of the rectangle. Conservative: false
// positives possible (the eye inside while the rectangle is not; faces
// within 1e-9 relative of the rectangle), false negatives not, for a closed
// volume.
bool shadowVolumeTouchesNearRectangle(const ShadowVolume& volume, const std::array<Vec3, 4>& nearCorners, Vec3 eye);

// ---- The 1994 paper's MUST_INTERSECT / CAN'T_INTERSECT checks (Figure 4,
// draw_shadow_volume): "A simple pre-shadow generation check using
// dot-products can determine if the object is on the appropriate side of
// the refracting plane and can save having to generate the shadow volume."

enum class FaceSide : std::uint8_t {
  LightSide,  // every vertex strictly on the light's side of the face's plane
  FarSide,    // every vertex strictly on the other side
  Straddles,  // some on each side, or touching the plane, or the light in the plane
};

// Where the object's triangles lie against the plane of a face, relative to
// the light (signs of the corners' signed distances, in double; exactly
// zero counts as touching). An object without triangles is FarSide (it
// casts nothing).
FaceSide classifyAgainstFace(const Mesh& object, const Plane& facePlane, Vec3 light);

// Whether the object's shadow reaches the face: some ray from the light
// meets one of the object's triangles and then the face polygon (convex,
// planar, any winding). Equivalently: the object meets the pyramid with
// apex at the light over the face. Tested per triangle by separating axes
// in double with a 1e-9 relative tolerance: conservative (touching and
// near-touching count as crossing; never false when a ray crosses). A
// FarSide object never crosses. In Figure 4's terms this is
// "intersect_face == ref_face": MUST_INTERSECT keeps the objects for which
// it is true, CAN'T_INTERSECT those for which it is false. The face's own
// object touches its pyramid's base, so it counts as crossing; callers
// skip it.
bool shadowCrossesFace(const Mesh& object, const std::vector<Vec3>& facePolygon, Vec3 light);

}  // namespace mpr
