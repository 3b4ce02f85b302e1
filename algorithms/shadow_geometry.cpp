#include "algorithms/shadow_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace mpr {
namespace {

using Key = std::tuple<float, float, float>;

// t > 0 where p + t d leaves the sphere (d unit); p inside or near it.
double exitDistance(DVec3 p, DVec3 d, const SceneBounds& b) {
  const DVec3 oc = p - b.centre;
  const double bq = glm::dot(oc, d), c = glm::dot(oc, oc) - b.radius * b.radius;
  const double disc = std::max(0.0, bq * bq - c);
  return std::max(-bq + std::sqrt(disc), 0.0) + 0.01 * b.radius;
}

// Segment [p, q] against triangle (a, b, c), in double.
bool segmentHitsTriangle(DVec3 p, DVec3 q, DVec3 a, DVec3 b, DVec3 c) {
  const DVec3 d = q - p, e1 = b - a, e2 = c - a;
  const DVec3 h = glm::cross(d, e2);
  const double det = glm::dot(e1, h);
  if (std::fabs(det) < 1e-300) return false;
  const double inv = 1.0 / det;
  const DVec3 s = p - a;
  const double u = glm::dot(s, h) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const DVec3 qv = glm::cross(s, e1);
  const double v = glm::dot(d, qv) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = glm::dot(e2, qv) * inv;
  return t >= 0.0 && t <= 1.0;
}

bool trianglesIntersect(const std::array<DVec3, 3>& t, const std::array<DVec3, 3>& u) {
  for (int i = 0; i < 3; ++i) {
    if (segmentHitsTriangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2])) return true;
    if (segmentHitsTriangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2])) return true;
  }
  return false;
}

}  // namespace

SceneBounds sceneBounds(const Scene& scene) {
  DVec3 lo(1e300), hi(-1e300);
  for (const SceneObject& o : scene.objects)
    for (const Vec3& p : o.mesh.positions) lo = glm::min(lo, DVec3(p)), hi = glm::max(hi, DVec3(p));
  SceneBounds b;
  if (lo.x > hi.x) return b;
  b.centre = (lo + hi) * 0.5;
  b.radius = std::max(glm::length(hi - lo) * 0.5, 1e-3);
  return b;
}

VolumeGeometry objectShadowVolume(const SceneObject& object, Vec3 lightF, const SceneBounds& bounds) {
  const Mesh& m = object.mesh;
  VolumeGeometry v;
  v.object = object.name;
  // Weld by exact position: primitives repeat vertices along hard edges.
  std::map<Key, std::uint32_t> ids;
  std::vector<DVec3> pos;
  std::vector<std::uint32_t> weld(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Vec3 p = m.positions[i];
    const auto [it, added] = ids.emplace(Key{p.x, p.y, p.z}, static_cast<std::uint32_t>(pos.size()));
    if (added) pos.emplace_back(p);
    weld[i] = it->second;
  }
  const DVec3 light(lightF);
  // Lit: the light strictly in front of the triangle's plane (decided in double).
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;  // directed edge -> +1 lit, -1 unlit
  std::vector<std::array<std::uint32_t, 3>> lit;
  for (const auto& t : m.triangles) {
    const std::array<std::uint32_t, 3> w = {weld[t[0]], weld[t[1]], weld[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;
    const DVec3 n = glm::cross(pos[w[1]] - pos[w[0]], pos[w[2]] - pos[w[0]]);
    if (!(glm::dot(n, n) > 0.0)) continue;
    const bool isLit = glm::dot(n, light - pos[w[0]]) > 0.0;
    if (isLit) lit.push_back(w);
    for (int k = 0; k < 3; ++k) edges[{w[k], w[(k + 1) % 3]}] = isLit ? 1 : -1;
  }
  auto far = [&](std::uint32_t i) {
    const DVec3 d = glm::normalize(pos[i] - light);
    return Vec3(pos[i] + d * exitDistance(pos[i], d, bounds));
  };
  for (const auto& [e, state] : edges) {
    const auto opposite = edges.find({e.second, e.first});
    if (opposite == edges.end()) v.closed = false;
    // A silhouette edge: lit on this side, unlit (or open) on the other.
    if (state != 1 || (opposite != edges.end() && opposite->second == 1)) continue;
    const Vec3 a(pos[e.first]), b(pos[e.second]), a2 = far(e.first), b2 = far(e.second);
    v.sides.push_back({b, a, a2});
    v.sides.push_back({b, a2, b2});
  }
  for (const auto& t : lit) {
    v.caps.push_back({Vec3(pos[t[0]]), Vec3(pos[t[1]]), Vec3(pos[t[2]])});
    v.caps.push_back({far(t[0]), far(t[2]), far(t[1])});
  }
  return v;
}

std::array<Vec3, 4> nearRectangle(const Camera& c, const DMat4& world, int width, int height) {
  const DVec3 eye(c.position), f = glm::normalize(DVec3(c.lookAt) - eye);
  const DVec3 s = glm::normalize(glm::cross(f, DVec3(c.up))), u = glm::cross(s, f);
  const double h = c.near * std::tan(glm::radians(static_cast<double>(c.fovY)) * 0.5);
  const double w = h * static_cast<double>(width) / static_cast<double>(height);
  const DMat4 back = glm::inverse(world);
  std::array<Vec3, 4> out;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    const DVec4 p = back * DVec4(eye + f * static_cast<double>(c.near) + s * (w * sx[i]) + u * (h * sy[i]), 1.0);
    out[static_cast<std::size_t>(i)] = Vec3(DVec3(p) / p.w);
  }
  return out;
}

bool pointInsideVolume(const VolumeGeometry& v, DVec3 p) {
  // A ray in a fixed direction no scene is aligned with; count crossings.
  const DVec3 q = p + DVec3(0.5772156649, 0.7071067812, 0.4142135624) * 1e6;
  int crossings = 0;
  for (const auto* list : {&v.sides, &v.caps})
    for (const auto& t : *list) crossings += segmentHitsTriangle(p, q, DVec3(t[0]), DVec3(t[1]), DVec3(t[2]));
  return crossings % 2 == 1;
}

bool volumeNeedsZFail(const VolumeGeometry& v, Vec3 eye, const std::array<Vec3, 4>& n) {
  if (pointInsideVolume(v, DVec3(eye))) return true;
  for (const Vec3& c : n)
    if (pointInsideVolume(v, DVec3(c))) return true;
  const std::array<DVec3, 3> r1 = {DVec3(n[0]), DVec3(n[1]), DVec3(n[2])}, r2 = {DVec3(n[0]), DVec3(n[2]), DVec3(n[3])};
  for (const auto* list : {&v.sides, &v.caps})
    for (const auto& t : *list) {
      const std::array<DVec3, 3> d = {DVec3(t[0]), DVec3(t[1]), DVec3(t[2])};
      if (trianglesIntersect(d, r1) || trianglesIntersect(d, r2)) return true;
    }
  return false;
}

}  // namespace mpr
