#include "algorithms/light_path.hpp"

#include <algorithm>

#include "algorithms/plane.hpp"
#include "algorithms/ref_light.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {

namespace {

using Polygon = std::vector<DVec3>;

// Sutherland-Hodgman against one plane: keeps signedDistance >= 0.
Polygon clipPolygon(const Polygon& poly, const Plane& plane) {
  Polygon out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const DVec3 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double da = plane.signedDistance(a), db = plane.signedDistance(b);
    if (da >= 0.0) out.push_back(a);
    if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

double polygonArea(const Polygon& poly) {
  DVec3 sum(0.0);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) sum += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return 0.5 * glm::length(sum);
}

// `poly` clipped to the light volume of `aperture` from `apex`: the part of
// the pyramid from the apex over the aperture that lies beyond the aperture.
Polygon clipToLightVolume(Polygon poly, const Polygon& aperture, DVec3 apex) {
  DVec3 centroid(0.0);
  for (const DVec3& a : aperture) centroid += a;
  centroid /= static_cast<double>(aperture.size());
  for (std::size_t i = 0; i < aperture.size() && !poly.empty(); ++i) {
    const DVec3 a = aperture[i], b = aperture[(i + 1) % aperture.size()];
    Plane side = Plane::throughPoint(glm::cross(a - apex, b - apex), apex);
    if (side.signedDistance(centroid) < 0.0) side = side.flipped();
    poly = clipPolygon(poly, side);
  }
  std::vector<Vec3> fl;
  for (const DVec3& a : aperture) fl.push_back(Vec3(a));
  Plane base = planeOfPolygon(fl);
  if (base.signedDistance(apex) > 0.0) base = base.flipped();
  return poly.empty() ? poly : clipPolygon(poly, base);
}

// The polygon the light leaves face f by: the face itself, a slab's shifted
// with the light.
Polygon leavingPolygon(const RefFace& f, DVec3 from, DVec3 to) {
  const DVec3 shift = leavingShift(f, from, to);
  Polygon p;
  for (const Vec3& v : f.polygon) p.push_back(DVec3(v) + shift);
  return p;
}

struct PathSearch {
  const std::vector<RefFace>& faces;
  int bounces;
  std::size_t limit;
  std::vector<LightPath>& out;
  bool over = false;

  void extend(const LightPath& path) {
    if (static_cast<int>(path.faces.size()) >= bounces) return;
    const DVec3 from = path.virtualLight();
    for (std::size_t g = 0; g < faces.size() && !over; ++g) {
      if (static_cast<int>(g) == path.faces.back()) continue;  // a plane never lights itself
      const RefFace& f = faces[g];
      const std::optional<DVec3> to = refLightPosition(f, from);
      if (!to) continue;
      // Some area of g inside every constituent light volume.
      Polygon lit;
      for (const Vec3& v : f.polygon) lit.push_back(DVec3(v));
      for (const Polygon& a : path.apertures)
        if (lit = clipToLightVolume(lit, a, from); lit.size() < 3) break;
      if (lit.size() < 3 || !(polygonArea(lit) > 0.0)) continue;
      LightPath next = path;
      next.faces.push_back(static_cast<int>(g));
      next.lights.push_back(*to);
      for (Polygon& a : next.apertures)
        for (DVec3& p : a) p = transferThroughFace(f, from, *to, p);
      next.apertures.push_back(leavingPolygon(f, from, *to));
      add(std::move(next));
    }
  }

  void add(LightPath path) {
    if (out.size() >= limit) {
      over = true;
      return;
    }
    out.push_back(std::move(path));
    const LightPath copy = out.back();  // `out` may grow while extending
    extend(copy);
  }
};

}  // namespace

DVec3 leavingShift(const RefFace& f, DVec3 from, DVec3 to) {
  return f.refracts() && f.thickness > 0.0 ? to - from : DVec3(0.0);
}

DVec3 carryAlongPath(const LightPath& path, const std::vector<RefFace>& faces, std::size_t from, DVec3 p) {
  for (std::size_t i = from; i < path.faces.size(); ++i)
    p = transferThroughFace(faces[static_cast<std::size_t>(path.faces[i])], path.lights[i], path.lights[i + 1], p);
  return p;
}

bool carryTurnsWinding(const LightPath& path, const std::vector<RefFace>& faces, std::size_t from) {
  bool turns = false;
  for (std::size_t i = from; i < path.faces.size(); ++i)
    turns ^= faces[static_cast<std::size_t>(path.faces[i])].kind == MaterialKind::Mirror;
  return turns;
}

std::vector<LightPath> lightPaths(const Scene& scene, const std::vector<RefFace>& faces, int bounces,
                                  std::size_t limit, bool* overLimit) {
  std::vector<LightPath> out;
  PathSearch search{faces, bounces, limit, out};
  for (std::size_t l = 0; l < scene.lights.size() && !search.over; ++l) {
    const DVec3 light(scene.lights[l].position);
    for (std::size_t fi = 0; fi < faces.size() && !search.over; ++fi) {
      const std::optional<DVec3> ref = refLightPosition(faces[fi], light);
      if (!ref) continue;
      LightPath p;
      p.light = static_cast<int>(l);
      p.faces = {static_cast<int>(fi)};
      p.lights = {light, *ref};
      p.apertures = {leavingPolygon(faces[fi], light, *ref)};
      search.add(std::move(p));
    }
  }
  if (overLimit) *overLimit = search.over;
  return out;
}

int lightBounces(const RenderSettings& render) {
  return render.lightBounces > 0 ? render.lightBounces : std::max(1, render.shadowRecursionDepth);
}

}  // namespace mpr
