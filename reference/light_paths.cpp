#include "reference/light_paths.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "reference/shading.hpp"
#include "reference/path_limits.hpp"
#include "reference/snell.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {
namespace {

constexpr int kMaxChainFaces = 8;

bool anyVertexOnSide(const SpecularFace& of, const SpecularFace& plane, double sign) {
  for (const DVec3& v : of.polygon)
    if (sign * plane.side(v) > kSurfaceEpsilon) return true;
  return false;
}

// Depth-first over face sequences, keeping those a light could take; each
// test is necessary for some point to be reached, never sufficient (the
// point's own walk decides).
struct ChainSearch {
  const std::vector<SpecularFace>& faces;
  double radius;
  int maxFaces;
  bool weightRule;
  std::vector<FaceChain>& out;

  // `source`: the (mirrored) light while it is known (no refraction yet);
  // `leave`: the side light leaves `prev` to (0: unknown).
  void extend(const FaceChain& chain, bool known, DVec3 source, int prev, double leave) {
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      const SpecularFace& face = faces[static_cast<std::size_t>(f)];
      const bool refracts = !face.mirror();
      const double w = chain.weight * face.weight;
      if (f == prev || (refracts && chain.refracting >= 0)) continue;  // a plane cannot pass light to itself
      if (static_cast<int>(chain.faces.size()) >= maxFaces || !(w > 0.0) || (weightRule && w < kMinPathWeight)) continue;
      if (prev >= 0) {
        const SpecularFace& p = faces[static_cast<std::size_t>(prev)];
        if (leave != 0.0 && !anyVertexOnSide(face, p, leave)) continue;
        if (face.mirror() && !anyVertexOnSide(p, face, 1.0)) continue;
      }
      const double s = known ? face.side(source) : 0.0;
      if (face.mirror() && known && !(s > -radius)) continue;  // a mirror lit from behind passes nothing on
      FaceChain next = chain;
      next.faces.push_back(f);
      next.weight = w;
      if (refracts) next.refracting = static_cast<int>(chain.faces.size());
      out.push_back(next);
      const double nextLeave = face.mirror() ? 1.0 : (known && std::fabs(s) > radius ? (s > 0.0 ? -1.0 : 1.0) : 0.0);
      extend(next, known && face.mirror(), face.mirror() ? face.reflect(source) : source, f, nextLeave);
    }
  }
};

// The points of one light path from the shading point to the light.
struct PathPoints {
  std::array<DVec3, 2 * kMaxChainFaces + 3> p;  // + 1: a slab's exit point
  int count = 0;
  void push(DVec3 v) { p[static_cast<std::size_t>(count++)] = v; }
};

// Walks from `from` to `target` across the mirrors chain.faces[k], k = begin,
// begin + step, ... != end, mirroring the target at each: the unfolded
// straight line (Fermat). Appends each crossing and the final target.
bool unfold(const LightPaths& lp, const FaceChain& chain, int begin, int end, int step, DVec3 from, DVec3 target,
            PathPoints& out) {
  for (int k = begin; k != end; k += step) {
    const SpecularFace& face = lp.faces[static_cast<std::size_t>(chain.faces[static_cast<std::size_t>(k)])];
    DVec3 x;
    if (!(face.side(from) > kSurfaceEpsilon) || !face.crossing(from, target, x) || !face.contains(x)) return false;
    out.push(x);
    from = x;
    target = face.reflect(target);
  }
  out.push(target);
  return true;
}

DVec3 reflectThrough(const LightPaths& lp, const FaceChain& chain, int begin, int end, int step, DVec3 p) {
  for (int k = begin; k != end; k += step) p = lp.faces[static_cast<std::size_t>(chain.faces[static_cast<std::size_t>(k)])].reflect(p);
  return p;
}

// A point of the disc of radius r about c facing `toward` (Duff et al. 2017's
// orthonormal basis about the disc's normal).
DVec3 discPoint(DVec3 c, double r, DVec2 d, DVec3 toward) {
  if (!(r > 0.0)) return c;
  const DVec3 w = glm::normalize(toward - c);
  const double sign = std::copysign(1.0, w.z), a = -1.0 / (sign + w.z), b = w.x * w.y * a;
  const DVec3 u(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x), v(b, sign + w.y * w.y * a, -w.y);
  return c + r * (d.x * u + d.y * v);
}

// The spreading of the light refracted at `face` from s to p, against a
// straight path of the same length: L^2 dOmega / dA_perp (1 without
// bending), the solid angle at s of the rays that reach a small square
// about p across the arriving ray, by finite differences of the crossing.
double refractedSpread(const SpecularFace& face, DVec3 s, DVec3 p, DVec3 x, double length) {
  const DVec3 arrive = glm::normalize(p - x);
  const DVec3 u = glm::normalize(glm::cross(arrive, std::fabs(arrive.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 1, 0)));
  const DVec3 v = glm::cross(arrive, u);
  const double h = 1e-5 * std::max(1.0, length);
  const std::optional<DVec3> xu = snellCrossing(face, s, p + h * u), xv = snellCrossing(face, s, p + h * v);
  if (!xu || !xv) return 1.0;
  const DVec3 w = glm::normalize(x - s), wu = glm::normalize(*xu - s) - w, wv = glm::normalize(*xv - s) - w;
  return length * length * glm::length(glm::cross(wu, wv)) / (h * h);
}

// The path through a chain for one point of the light (centre c); `spread`
// gets the refracted light's spreading where asked for (else 1).
bool chainPath(const LightPaths& lp, const FaceChain& chain, DVec3 p, DVec3 c, double r, DVec2 disc, DVec2 scatter,
               PathPoints& out, double* spread) {
  if (spread) *spread = 1.0;
  const int n = static_cast<int>(chain.faces.size()), j = chain.refracting;
  out.count = 0;
  out.push(p);
  if (j < 0) {
    // The light's image through every mirror, its disc facing the point.
    const DVec3 image = reflectThrough(lp, chain, 0, n, 1, c);
    return unfold(lp, chain, n - 1, -1, -1, p, discPoint(image, r, disc, p), out);
  }
  // Mirrors on either side of the refracting face unfold towards it: the
  // point's image through the faces after it, the light's through those before.
  const SpecularFace& face = lp.faces[static_cast<std::size_t>(chain.faces[static_cast<std::size_t>(j)])];
  const DVec3 pImage = reflectThrough(lp, chain, n - 1, j, -1, p);
  const DVec3 sImage = discPoint(reflectThrough(lp, chain, 0, j, 1, c), r, disc, face.centre);
  // A point on the face itself (its own lit colour) gets no light through it.
  if (!(std::fabs(face.side(pImage)) > kSurfaceEpsilon) || !(std::fabs(face.side(sImage)) > kSurfaceEpsilon)) return false;
  // Frosted glass scatters the light it passes on as it scatters the view
  // through it (ray_tracer.cpp; 1997 §3): by reciprocity the point is lit as
  // if it stood moved along the face's tangents by shear times its distance
  // behind the face times a normal pair (one per light point and pixel
  // sample). The crossing is solved for that point; the last leg still ends
  // at the point itself.
  DVec3 target = pImage;
  if (face.shear > 0.0) {
    const DVec3 u = perpendicular(face.normal), v = glm::cross(face.normal, u);
    target = pImage + face.shear * std::fabs(face.side(pImage)) * (scatter.x * u + scatter.y * v);
  }
  if (face.thickness > 0.0) {
    // A slab (in-out refraction): the light enters at x and goes on parallel
    // to itself from x + shift (no spreading: every ray is shifted alike to
    // first order; the spread stays 1).
    const std::optional<DVec3> x = slabCrossing(face, sImage, target);
    if (!x || !face.contains(*x)) return false;
    // And only where the slab stands in the light's way (the straight ray
    // crosses the face too): a ray shifted past the slab's edge leaves by
    // its side, not its far face (as the pipeline's light volume is cut to
    // the slab's own shadow, algorithms/ref_light.cpp).
    {
      const double ss = face.side(sImage), sp = face.side(target);
      if (!face.contains(sImage + (target - sImage) * (ss / (ss - sp)))) return false;
    }
    const DVec3 exit = *x + slabShift(glm::normalize(*x - sImage), face.normal, face.ior, face.thickness);
    PathPoints toPoint;
    if (!unfold(lp, chain, j + 1, n, 1, exit, pImage, toPoint)) return false;
    for (int i = toPoint.count - 2; i >= 0; --i) out.push(toPoint.p[static_cast<std::size_t>(i)]);
    out.push(exit);
    out.push(*x);
    return unfold(lp, chain, j - 1, -1, -1, *x, sImage, out);
  }
  const std::optional<DVec3> x = snellCrossing(face, sImage, target);
  if (!x || !face.contains(*x)) return false;
  PathPoints toPoint;
  if (!unfold(lp, chain, j + 1, n, 1, *x, pImage, toPoint)) return false;
  for (int i = toPoint.count - 2; i >= 0; --i) out.push(toPoint.p[static_cast<std::size_t>(i)]);  // back from the point
  out.push(*x);
  if (!unfold(lp, chain, j - 1, -1, -1, *x, sImage, out)) return false;
  // Mirrors are isometries: the spreading is the refracting face's alone,
  // between the unfolded light and point.
  if (spread) *spread = refractedSpread(face, sImage, target, *x, glm::length(*x - sImage) + glm::length(target - *x));
  return true;
}

}  // namespace

LightPaths findLightPaths(const Scene& scene, int bounces) {
  LightPaths lp;
  lp.faces = findSpecularFaces(scene);
  const int maxFaces = bounces < 0 ? kMaxChainFaces : std::min(bounces, kMaxChainFaces);
  for (const PointLight& l : scene.lights) {
    lp.chains.emplace_back();
    ChainSearch search{lp.faces, static_cast<double>(l.radius), maxFaces, bounces < 0, lp.chains.back()};
    search.extend(FaceChain{}, true, DVec3(l.position), -1, 0.0);
  }
  return lp;
}

bool blocked(const Bvh& bvh, DVec3 a, DVec3 b, std::uint64_t& shadowRays) {
  const DVec3 d = b - a;
  const double len = glm::length(d);
  if (!(len > 2.0 * kSurfaceEpsilon)) return false;
  ++shadowRays;
  return bvh.occluded(Ray{a, d / len}, kSurfaceEpsilon, len - kSurfaceEpsilon);
}

DVec3 directLight(const Scene& scene, const Bvh& bvh, const LightPaths& lp, const ShadingPoint& at,
                  ShadingModel model, const LightSampling& sampling, std::uint64_t& shadowRays) {
  DVec3 sum(0.0);
  PathPoints path;
  // One path's light: its first leg's direction, its unfolded length for
  // the attenuation; shadow rays only where it would add something.
  const auto add = [&](const PointLight& light, DVec3 colour) {
    double length = 0.0;
    for (int i = 1; i < path.count; ++i) length += glm::length(path.p[i] - path.p[i - 1]);
    const DVec3 toLight = glm::normalize(path.p[1] - path.p[0]);
    const DVec3 term = lightTerm(*at.material, model, at.normal, at.toViewer, toLight, colour * glAttenuation(light, length));
    if (term == DVec3(0.0)) return;
    for (int i = 1; i < path.count; ++i)
      if (blocked(bvh, path.p[i - 1], path.p[i], shadowRays)) return;
    sum += term;
  };
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const PointLight& light = scene.lights[l];
    const double r = light.radius;
    const std::uint32_t points = r > 0.0 ? sampling.perSample : 1;
    const DVec3 colour = DVec3(light.color) / static_cast<double>(points), centre(light.position);
    for (std::uint32_t k = 0; k < points; ++k) {
      const DVec2 disc =
          r > 0.0 ? concentricDisc(sampling.sampler->lightPoint(sampling.sample, k, points, sampling.depth)) : DVec2(0.0);
      path.count = 0;
      path.push(at.position);
      path.push(discPoint(centre, r, disc, at.position));
      add(light, colour);
      // The physical model adds the refracted light's spreading (a caustic's
      // Jacobian) that the pipeline's virtual lights lack.
      double spread = 1.0;
      double* wantSpread = model == ShadingModel::Physical ? &spread : nullptr;
      const DVec2 scatter = sampling.sampler ? sampling.sampler->lightScatter(sampling.sample, k, sampling.depth) : DVec2(0.0);
      for (const FaceChain& chain : lp.chains[l])
        if (chainPath(lp, chain, at.position, centre, r, disc, scatter, path, wantSpread))
          add(light, colour * (chain.weight * spread));
    }
  }
  return sum;
}

}  // namespace mpr
