#pragma once
// Helpers shared by the shadow-geometry tests: placed boxes, edge-balance
// checks, a portable deterministic random source, and
// small exact-enough geometry used as the tests' independent truth.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "algorithms/plane.hpp"
#include "algorithms/shadow_volume.hpp"
#include "scene/primitives.hpp"

namespace mpr::test {

using PosKey = std::tuple<float, float, float>;
inline PosKey key(Vec3 p) { return {p.x, p.y, p.z}; }

inline Mesh boxAt(Vec3 centre, Vec3 size = Vec3(1.0f)) {
  Mesh m = makeBox();
  transformMesh(m, glm::scale(glm::translate(Mat4(1.0f), centre), size));
  return m;
}

inline Mesh concat(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const auto base = static_cast<std::uint32_t>(a.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  for (auto f : b.faces) {
    for (auto& i : f) i += base;
    m.faces.push_back(f);
  }
  return m;
}

// Directed edges of a triangle soup, by exact positions, with counts.
inline std::map<std::pair<PosKey, PosKey>, int> directedEdges(const std::vector<VolumeTriangle>& tris) {
  std::map<std::pair<PosKey, PosKey>, int> e;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) e[{key(t[static_cast<std::size_t>(k)]), key(t[static_cast<std::size_t>((k + 1) % 3)])}] += 1;
  return e;
}

// Every directed edge used exactly once and its reverse exactly once: a
// watertight, consistently oriented 2-manifold surface.
inline int manifoldEdgeViolations(const std::vector<VolumeTriangle>& tris) {
  const auto e = directedEdges(tris);
  int bad = 0;
  for (const auto& [edge, n] : e) {
    const auto rev = e.find({edge.second, edge.first});
    if (n != 1 || rev == e.end() || rev->second != 1) ++bad;
  }
  return bad;
}

// Every directed edge used as often as its reverse: a closed oriented
// surface, possibly touching itself along edges.
inline int balanceViolations(const std::vector<VolumeTriangle>& tris) {
  const auto e = directedEdges(tris);
  int bad = 0;
  for (const auto& [edge, n] : e) {
    const auto rev = e.find({edge.second, edge.first});
    if (rev == e.end() || rev->second != n) ++bad;
  }
  return bad;
}

inline DVec3 areaVector(const VolumeTriangle& t) {
  return 0.5 * glm::cross(DVec3(t[1]) - DVec3(t[0]), DVec3(t[2]) - DVec3(t[0]));
}

// Enclosed volume by the divergence theorem (positive when outward).
inline double enclosedVolume(const std::vector<VolumeTriangle>& tris) {
  double v = 0.0;
  for (const auto& t : tris) v += glm::dot(DVec3(t[0]), glm::cross(DVec3(t[1]), DVec3(t[2]))) / 6.0;
  return v;
}

// A deterministic, portable random source (SplitMix64): the same numbers
// on every standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : s_(seed) {}
  double uniform(double lo, double hi) {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) / 9007199254740992.0;
  }
  Vec3 point(double lo, double hi) {
    const double x = uniform(lo, hi), y = uniform(lo, hi), z = uniform(lo, hi);
    return Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
  }

 private:
  std::uint64_t s_;
};

// Closest point of triangle a, b, c to p (Ericson, Real-Time Collision
// Detection, 5.1.5), in double.
inline DVec3 closestPointOnTriangle(DVec3 p, DVec3 a, DVec3 b, DVec3 c) {
  const DVec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const DVec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const DVec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

inline DVec3 closestPointOnSegment(DVec3 p, DVec3 a, DVec3 b) {
  const DVec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  if (!(len2 > 0.0)) return a;
  return a + ab * std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0);
}

// Does the segment p -> q pass through triangle a, b, c (proper crossing,
// signed volumes in double)? Returns +1 when it enters through the front
// (the triangle faces p), -1 through the back, 0 when it misses.
inline int segmentCrossing(DVec3 p, DVec3 q, DVec3 a, DVec3 b, DVec3 c) {
  auto vol = [](DVec3 u, DVec3 v, DVec3 w, DVec3 x) { return glm::dot(glm::cross(v - u, w - u), x - u); };
  const double sp = vol(a, b, c, p), sq = vol(a, b, c, q);
  if ((sp > 0) == (sq > 0) || sp == 0 || sq == 0) return 0;
  const double e1 = vol(p, q, a, b), e2 = vol(p, q, b, c), e3 = vol(p, q, c, a);
  const bool allPos = e1 > 0 && e2 > 0 && e3 > 0, allNeg = e1 < 0 && e2 < 0 && e3 < 0;
  if (!allPos && !allNeg) return 0;
  return sp > 0 ? 1 : -1;
}

// Does the segment from p to q meet the axis-aligned box [lo, hi] (slabs)?
inline bool segmentHitsBox(DVec3 p, DVec3 q, DVec3 lo, DVec3 hi) {
  double t0 = 0.0, t1 = 1.0;
  const DVec3 d = q - p;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (p[i] < lo[i] || p[i] > hi[i]) return false;
      continue;
    }
    double a = (lo[i] - p[i]) / d[i], b = (hi[i] - p[i]) / d[i];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

inline bool allFinite(const std::vector<VolumeTriangle>& tris) {
  for (const auto& t : tris)
    for (const Vec3& p : t)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

}  // namespace mpr::test
