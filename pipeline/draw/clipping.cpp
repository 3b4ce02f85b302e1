#include "pipeline/draw/clipping.hpp"

namespace mpr {

const std::vector<ClipPlane>& viewVolumePlanes() {
  static const std::vector<ClipPlane> planes = {
      {0, 0, 1, 1},            // z >= -w (near)
      {0, 0, -1, 1},           // z <= w  (far)
      {1, 0, 0, kGuardBand},   // x >= -G w
      {-1, 0, 0, kGuardBand},  // x <= G w
      {0, 1, 0, kGuardBand},
      {0, -1, 0, kGuardBand},
  };
  return planes;
}

namespace {

float distance(const ClipPlane& p, const Vec4& v) {
  return p.x * v.x + p.y * v.y + p.z * v.z + p.w * v.w;
}

ClipVertex interpolate(const ClipVertex& in, const ClipVertex& out, float t) {
  ClipVertex r;
  r.clip = in.clip + t * (out.clip - in.clip);
  for (int i = 0; i < kVaryings; ++i) r.attr[i] = in.attr[i] + t * (out.attr[i] - in.attr[i]);
  return r;
}

}  // namespace

bool insideAllPlanes(const std::array<ClipVertex, 3>& tri, std::span<const ClipPlane> planes) {
  for (const ClipPlane& plane : planes)
    for (const ClipVertex& v : tri)
      if (!(distance(plane, v.clip) >= 0.0f)) return false;
  return true;
}

std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> poly, const std::vector<ClipPlane>& planes) {
  std::vector<ClipVertex> next;
  std::vector<float> dist;
  for (const ClipPlane& plane : planes) {
    if (poly.empty()) break;
    dist.resize(poly.size());
    bool allInside = true;
    for (size_t i = 0; i < poly.size(); ++i) {
      dist[i] = distance(plane, poly[i].clip);
      allInside = allInside && dist[i] >= 0.0f;
    }
    if (allInside) continue;
    next.clear();
    for (size_t i = 0; i < poly.size(); ++i) {
      const size_t j = (i + 1) % poly.size();
      const bool inI = dist[i] >= 0.0f, inJ = dist[j] >= 0.0f;
      if (inI) next.push_back(poly[i]);
      if (inI != inJ) {
        const size_t in = inI ? i : j, out = inI ? j : i;
        const float t = dist[in] / (dist[in] - dist[out]);
        next.push_back(interpolate(poly[in], poly[out], t));
      }
    }
    poly.swap(next);
  }
  return poly;
}

}  // namespace mpr
