#include "scene/tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace mpr {
namespace {

bool lexicallyLess(const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

// The point m/k of the way along the edge (u, v), the same from either end.
Vec3 edgePoint(Vec3 u, Vec3 v, int m, int k) {
  if (lexicallyLess(v, u)) std::swap(u, v), m = k - m;
  // The ends themselves, exactly: u + (v - u) * 1 need not round to v, and
  // a corner off by an ulp opens the mesh (a tessellated box's shadow
  // volume was counted as open).
  if (m == 0) return u;
  if (m == k) return v;
  const float t = static_cast<float>(m) / static_cast<float>(k);
  return u + (v - u) * t;
}

float longestEdge(const Mesh& mesh) {
  float longest = 0.0f;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      longest = std::max(longest, glm::length(mesh.positions[t[e]] - mesh.positions[t[(e + 1) % 3]]));
  return longest;
}

// Triangle (a, b, c) as the k x k lattice of barycentric points (i/k, j/k):
// i along a->b, j along a->c, counter-clockwise as the triangle is.
void splitTriangle(const Mesh& in, const std::array<std::uint32_t, 3>& t, int k, Mesh& out) {
  const Vec3 a = in.positions[t[0]], b = in.positions[t[1]], c = in.positions[t[2]];
  const Vec3 na = in.normals[t[0]], nb = in.normals[t[1]], nc = in.normals[t[2]];
  std::vector<std::uint32_t> index((k + 1) * (k + 1));
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i + j <= k; ++i) {
      Vec3 p;
      if (j == 0) p = edgePoint(a, b, i, k);
      else if (i == 0) p = edgePoint(a, c, j, k);
      else if (i + j == k) p = edgePoint(b, c, j, k);
      else p = a + (b - a) * (static_cast<float>(i) / k) + (c - a) * (static_cast<float>(j) / k);
      const float wb = static_cast<float>(i) / k, wc = static_cast<float>(j) / k;
      Vec3 n = na * (1.0f - wb - wc) + nb * wb + nc * wc;
      const float len = glm::length(n);
      if (len > 0.0f) n /= len;
      index[j * (k + 1) + i] = static_cast<std::uint32_t>(out.positions.size());
      out.positions.push_back(p);
      out.normals.push_back(n);
    }
  const auto at = [&](int i, int j) { return index[j * (k + 1) + i]; };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      out.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < k) out.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

// Auto: the object's longest edge over its bounding box's distance to the
// nearest light (a lower bound of every edge's: the ratio errs on the side
// of more splits, and costs one pass over the edges and one per light).
double longestEdgeOverLightDistance(const Scene& scene, const Mesh& mesh, float longest) {
  if (scene.lights.empty()) return 0.0;
  Vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const Vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  double nearest = std::numeric_limits<double>::infinity();
  for (const PointLight& l : scene.lights) {
    const DVec3 p(l.position);
    nearest = std::min(nearest, glm::length(p - glm::clamp(p, DVec3(lo), DVec3(hi))));
  }
  return nearest > 0.0 ? static_cast<double>(longest) / nearest : std::numeric_limits<double>::infinity();
}

// The k an object's edges are divided into (1: the object is kept as it is).
int divisions(const Scene& scene, const SceneObject& o, float maxEdge) {
  if (!(maxEdge > 0.0f) && maxEdge != kAutoTessellation) return 1;
  if (scene.materials[static_cast<std::size_t>(o.material)].specularKind() || o.mesh.triangles.empty()) return 1;
  // Compared as a float first: a huge or NaN ratio must not reach the int.
  const float wanted =
      maxEdge == kAutoTessellation
          ? static_cast<float>(std::ceil(longestEdgeOverLightDistance(scene, o.mesh, longestEdge(o.mesh)) /
                                         kAutoEdgeOverLightDistance))
          : std::ceil(longestEdge(o.mesh) / maxEdge);
  const int most = maxEdge == kAutoTessellation ? kMaxAutoTessellationDivisions : kMaxTessellationDivisions;
  int k = wanted >= static_cast<float>(most) ? most : wanted >= 1.0f ? static_cast<int>(wanted) : 1;
  while (k > 1 && o.mesh.triangles.size() * static_cast<std::size_t>(k) * k > kMaxTessellatedTriangles) --k;
  return k;
}

}  // namespace

std::uint64_t tessellatedTriangleCount(const Scene& scene, float maxEdge) {
  std::uint64_t n = 0;
  for (const SceneObject& o : scene.objects) {
    const auto k = static_cast<std::uint64_t>(divisions(scene, o, maxEdge));
    n += o.mesh.triangles.size() * k * k;
  }
  return n;
}

void tessellateLitObjects(Scene& scene, float maxEdge) {
  for (SceneObject& o : scene.objects) {
    const int k = divisions(scene, o, maxEdge);
    if (k == 1) continue;
    // Faces matter only to specular objects (planar-face checks, ref faces):
    // a lit object's are not kept.
    Mesh out;
    for (const auto& t : o.mesh.triangles) splitTriangle(o.mesh, t, k, out);
    o.mesh = std::move(out);
  }
}

}  // namespace mpr
