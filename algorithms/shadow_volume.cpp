#include "algorithms/shadow_volume.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mpr {
namespace {

// Relative tolerance of the conservative contact tests: far above double
// rounding of the inputs' arithmetic, far below anything a pixel resolves.
constexpr double kContactTolerance = 1e-9;

DVec3 unit(DVec3 v) {
  const double len = glm::length(v);
  return len > 0.0 ? v / len : DVec3(0.0);
}

// Separating-axis contact test of two convex point sets. Candidate axes
// that vanish (parallel edges) are skipped: fewer axes can only turn a
// separation into a (false) contact, never the reverse.
class ContactTest {
 public:
  ContactTest(const DVec3* a, std::size_t na, const DVec3* b, std::size_t nb) : a_(a), na_(na), b_(b), nb_(nb) {
    double scale = 0.0;
    for (std::size_t i = 0; i < na; ++i) scale = std::max(scale, glm::length(a[i] - a[0]));
    for (std::size_t i = 0; i < nb; ++i) scale = std::max(scale, glm::length(b[i] - a[0]));
    tol_ = kContactTolerance * std::max(scale, std::numeric_limits<double>::min());
  }
  // True when `axis` separates the sets by more than the tolerance.
  bool separates(DVec3 axis) const {
    const double len = glm::length(axis);
    if (!(len > 1e-12)) return false;
    axis /= len;
    double loA = std::numeric_limits<double>::infinity(), hiA = -loA, loB = loA, hiB = -loA;
    for (std::size_t i = 0; i < na_; ++i) {
      const double d = glm::dot(axis, a_[i]);
      loA = std::min(loA, d), hiA = std::max(hiA, d);
    }
    for (std::size_t i = 0; i < nb_; ++i) {
      const double d = glm::dot(axis, b_[i]);
      loB = std::min(loB, d), hiB = std::max(hiB, d);
    }
    return hiA < loB - tol_ || hiB < loA - tol_;
  }

 private:
  const DVec3* a_;
  std::size_t na_;
  const DVec3* b_;
  std::size_t nb_;
  double tol_ = 0.0;
};

// The triangle's own candidate axes: its normal and its in-plane edge
// normals (the latter decide coplanar and flat cases).
bool triangleAxesSeparate(const ContactTest& test, const std::array<DVec3, 3>& t, std::array<DVec3, 3>& edges) {
  for (int k = 0; k < 3; ++k) edges[static_cast<std::size_t>(k)] = unit(t[static_cast<std::size_t>((k + 1) % 3)] - t[static_cast<std::size_t>(k)]);
  const DVec3 n = unit(glm::cross(edges[0], edges[1]));
  if (test.separates(n)) return true;
  for (const DVec3& e : edges)
    if (test.separates(glm::cross(n, e))) return true;
  return false;
}

// The solid angle of triangle a, b, c seen from the origin (Van Oosterom &
// Strackee), signed: positive when the triangle winds counter-clockwise
// seen from the origin's far side, i.e. when the origin is behind it.
double solidAngle(DVec3 a, DVec3 b, DVec3 c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double num = glm::dot(a, glm::cross(b, c));
  const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(num, den);
}

}  // namespace

std::vector<VolumeTriangle> ShadowVolume::triangles() const {
  std::vector<VolumeTriangle> out;
  out.reserve(lightCap.size() + 2 * sides.size() + darkCap.size());
  out.insert(out.end(), lightCap.begin(), lightCap.end());
  for (const auto& q : sides) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  }
  out.insert(out.end(), darkCap.begin(), darkCap.end());
  return out;
}

double shadowExtrusionRadius(const Mesh& mesh, const std::vector<std::uint32_t>& litTriangles, Vec3 lightF,
                             const BoundingSphere& receivers) {
  if (litTriangles.empty()) return 0.0;
  const DVec3 light(lightF);
  // Every cap point must end up farther from the light than any receiver
  // point and than any point of the caster itself (else the dark cap would
  // pass in front of the light cap on some ray).
  double reach = glm::length(receivers.centre - light) + receivers.radius;
  // A cap triangle with corners at distance R from the light is R times the
  // triangle of the corners' unit directions; every point of it is at least
  // R times that triangle's plane distance from the light.
  double minPlane = 1.0;
  for (const std::uint32_t t : litTriangles) {
    std::array<DVec3, 3> u;
    for (std::size_t k = 0; k < 3; ++k) {
      const DVec3 d = DVec3(mesh.positions[mesh.triangles[t][k]]) - light;
      reach = std::max(reach, glm::length(d));
      u[k] = unit(d);
    }
    const DVec3 n = glm::cross(u[1] - u[0], u[2] - u[0]);
    const double nl = glm::length(n);
    if (nl > 0.0) minPlane = std::min(minPlane, std::fabs(glm::dot(n, u[0])) / nl);
  }
  minPlane = std::max(minPlane, 1e-6);
  return reach / minPlane * 1.001;
}

Vec3 extrudeFromLight(Vec3 v, Vec3 lightF, double R) {
  const DVec3 light(lightF);
  return Vec3(light + R * unit(DVec3(v) - light));
}

ShadowVolume buildShadowVolume(const Mesh& mesh, const Silhouette& s, Vec3 light, const BoundingSphere& receivers) {
  ShadowVolume v;
  v.light = light;
  v.casterClosed = s.closed;
  v.casterBoundaryEdges = s.boundaryEdgeCount;
  v.extrusionRadius = shadowExtrusionRadius(mesh, s.litTriangles, light, receivers);
  if (s.litTriangles.empty()) return v;
  const double R = v.extrusionRadius;
  for (const std::uint32_t t : s.litTriangles) {
    const auto& tri = mesh.triangles[t];
    const Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    v.lightCap.push_back({a, b, c});
    v.darkCap.push_back({extrudeFromLight(a, light, R), extrudeFromLight(c, light, R), extrudeFromLight(b, light, R)});
  }
  for (const SilhouetteEdge& e : s.edges)
    v.sides.push_back({e.pa, e.pb, extrudeFromLight(e.pb, light, R), extrudeFromLight(e.pa, light, R)});
  return v;
}

ShadowVolume buildShadowVolume(const Mesh& mesh, Vec3 light, const BoundingSphere& receivers) {
  const MeshConnectivity conn = buildMeshConnectivity(mesh);
  return buildShadowVolume(mesh, findSilhouette(mesh, conn, light), light, receivers);
}

BoundingSphere boundingSphereOf(const std::vector<Vec3>& points) {
  BoundingSphere s;
  if (points.empty()) return s;
  DVec3 lo(points[0]), hi(points[0]);
  for (const Vec3& p : points) lo = glm::min(lo, DVec3(p)), hi = glm::max(hi, DVec3(p));
  s.centre = (lo + hi) * 0.5;
  for (const Vec3& p : points) s.radius = std::max(s.radius, glm::length(DVec3(p) - s.centre));
  return s;
}

BoundingSphere sceneBoundingSphere(const Scene& scene) {
  std::vector<Vec3> all;
  for (const SceneObject& o : scene.objects) all.insert(all.end(), o.mesh.positions.begin(), o.mesh.positions.end());
  return boundingSphereOf(all);
}

double shadowVolumeWinding(const ShadowVolume& volume, Vec3 pF) {
  const DVec3 p(pF);
  double sum = 0.0;
  for (const VolumeTriangle& t : volume.triangles())
    sum += solidAngle(DVec3(t[0]) - p, DVec3(t[1]) - p, DVec3(t[2]) - p);
  return sum / (4.0 * std::numbers::pi);
}

bool pointInsideShadowVolume(const ShadowVolume& volume, Vec3 p) {
  return !volume.empty() && shadowVolumeWinding(volume, p) > 0.5;
}

bool trianglesMayIntersect(const std::array<DVec3, 3>& t, const std::array<DVec3, 3>& u) {
  const ContactTest test(t.data(), 3, u.data(), 3);
  std::array<DVec3, 3> et, eu;
  if (triangleAxesSeparate(test, t, et) || triangleAxesSeparate(test, u, eu)) return false;
  for (const DVec3& a : et)
    for (const DVec3& b : eu)
      if (test.separates(glm::cross(a, b))) return false;
  return true;
}

std::array<Vec3, 4> nearPlaneCorners(Vec3 eyeF, Vec3 lookAtF, Vec3 upF, double fovYDegrees, double aspect,
                                     double zNear) {
  // gluLookAt: f towards the centre, s = f x up, u = s x f.
  const DVec3 eye(eyeF), f = unit(DVec3(lookAtF) - eye);
  DVec3 s = unit(glm::cross(f, DVec3(upF)));
  if (glm::length(s) == 0.0)
    s = unit(glm::cross(f, std::fabs(f.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0)));
  const DVec3 u = glm::cross(s, f);
  // gluPerspective: the near rectangle's half height is near * tan(fovY / 2).
  const double h = zNear * std::tan(fovYDegrees * std::numbers::pi / 360.0), w = h * aspect;
  const DVec3 c = eye + f * zNear;
  return {Vec3(c - s * w - u * h), Vec3(c + s * w - u * h), Vec3(c + s * w + u * h), Vec3(c - s * w + u * h)};
}

std::array<Vec3, 4> nearPlaneCorners(const Camera& camera, double aspect) {
  return nearPlaneCorners(camera.position, camera.lookAt, camera.up, camera.fovY, aspect, camera.near);
}

bool shadowVolumeTouchesNearRectangle(const ShadowVolume& volume, const std::array<Vec3, 4>& n, Vec3 eye) {
  if (volume.empty()) return false;
  // The rectangle wholly inside (or the eye: conservative).
  if (pointInsideShadowVolume(volume, eye)) return true;
  for (const Vec3& c : n)
    if (pointInsideShadowVolume(volume, c)) return true;
  // The rectangle partly inside: then the surface crosses it.
  const std::array<DVec3, 3> r1 = {DVec3(n[0]), DVec3(n[1]), DVec3(n[2])};
  const std::array<DVec3, 3> r2 = {DVec3(n[0]), DVec3(n[2]), DVec3(n[3])};
  for (const VolumeTriangle& t : volume.triangles()) {
    const std::array<DVec3, 3> d = {DVec3(t[0]), DVec3(t[1]), DVec3(t[2])};
    if (trianglesMayIntersect(d, r1) || trianglesMayIntersect(d, r2)) return true;
  }
  return false;
}

FaceSide classifyAgainstFace(const Mesh& object, const Plane& plane, Vec3 light) {
  const double sl = plane.signedDistance(light);
  bool lightSide = false, farSide = false, touching = false;
  for (const auto& tri : object.triangles)
    for (const std::uint32_t i : tri) {
      const double s = plane.signedDistance(object.positions[i]);
      if (s == 0.0 || sl == 0.0) touching = true;
      else if ((s > 0.0) == (sl > 0.0)) lightSide = true;
      else farSide = true;
    }
  if (touching || (lightSide && farSide)) return FaceSide::Straddles;
  return lightSide ? FaceSide::LightSide : FaceSide::FarSide;
}

bool shadowCrossesFace(const Mesh& object, const std::vector<Vec3>& polygon, Vec3 lightF) {
  if (polygon.size() < 3) return false;
  const Plane plane = planeOfPolygon(polygon);
  // Rays leave the light, so past a far-side object they only move away
  // from the plane.
  if (classifyAgainstFace(object, plane, lightF) == FaceSide::FarSide) return false;

  // The pyramid (light, face): its points, edges and face normals.
  const DVec3 light(lightF);
  const std::size_t n = polygon.size();
  std::vector<DVec3> pyramid{light};
  for (const Vec3& p : polygon) pyramid.emplace_back(p);
  std::vector<DVec3> edges, normals{plane.normal};
  for (std::size_t i = 0; i < n; ++i) {
    const DVec3 lateral = unit(pyramid[1 + i] - light), rim = unit(pyramid[1 + (i + 1) % n] - pyramid[1 + i]);
    edges.push_back(lateral);
    edges.push_back(rim);
    normals.push_back(glm::cross(lateral, unit(pyramid[1 + (i + 1) % n] - light)));
    // In-plane normals: they decide when the light lies in the face's plane
    // and the pyramid is flat.
    normals.push_back(glm::cross(plane.normal, lateral));
    normals.push_back(glm::cross(plane.normal, rim));
  }

  for (const auto& tri : object.triangles) {
    const std::array<DVec3, 3> t = {DVec3(object.positions[tri[0]]), DVec3(object.positions[tri[1]]),
                                    DVec3(object.positions[tri[2]])};
    const ContactTest test(pyramid.data(), pyramid.size(), t.data(), 3);
    std::array<DVec3, 3> et;
    bool separated = triangleAxesSeparate(test, t, et);
    for (std::size_t i = 0; !separated && i < normals.size(); ++i) separated = test.separates(normals[i]);
    for (std::size_t i = 0; !separated && i < edges.size(); ++i)
      for (const DVec3& e : et)
        if ((separated = test.separates(glm::cross(edges[i], e)))) break;
    if (!separated) return true;
  }
  return false;
}

}  // namespace mpr
