#include "reference/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mpr {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kLeafSize = 4;
// The traversal stack holds at most one entry per level plus one.
constexpr int kMaxTreeDepth = 60;

struct Box {
  DVec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  void grow(DVec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void grow(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  double area() const {
    const DVec3 d = hi - lo;
    return d.x < 0.0 ? 0.0 : 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

Box boxOf(const BvhTriangle& t) {
  Box b;
  b.grow(t.p0), b.grow(t.p0 + t.e1), b.grow(t.p0 + t.e2);
  return b;
}

struct Builder {
  std::vector<BvhTriangle>& tris;
  std::vector<Bvh::Node>& nodes;
  std::vector<Box> boxes;
  std::vector<DVec3> centres;
  std::vector<std::uint32_t> order;

  // Builds the node for order[first, first + count) depth first, so that an
  // inner node's first child follows it.
  void build(std::uint32_t first, std::uint32_t count, int depth) {
    const std::uint32_t index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    Box bounds, centreBounds;
    for (std::uint32_t i = first; i < first + count; ++i) bounds.grow(boxes[order[i]]), centreBounds.grow(centres[order[i]]);
    nodes[index].lo = bounds.lo, nodes[index].hi = bounds.hi;
    if (count <= kLeafSize || depth >= kMaxTreeDepth) return leaf(index, first, count);
    // Binned SAH (Wald 2007): the cheapest of kBins - 1 planes per axis.
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centreBounds.lo[axis], extent = centreBounds.hi[axis] - lo;
      if (!(extent > 0.0)) continue;
      std::array<Box, kBins> bin;
      std::array<std::uint32_t, kBins> n{};
      for (std::uint32_t i = first; i < first + count; ++i) {
        const int b = binOf(centres[order[i]][axis], lo, extent);
        bin[b].grow(boxes[order[i]]), ++n[b];
      }
      std::array<double, kBins> rightCost{};
      Box right;
      std::uint32_t nr = 0;
      for (int b = kBins - 1; b > 0; --b) right.grow(bin[b]), nr += n[b], rightCost[b] = right.area() * nr;
      Box left;
      std::uint32_t nl = 0;
      for (int b = 0; b + 1 < kBins; ++b) {
        left.grow(bin[b]), nl += n[b];
        const double cost = left.area() * nl + rightCost[b + 1];
        if (nl > 0 && nl < count && cost < bestCost) bestCost = cost, bestAxis = axis, bestSplit = b;
      }
    }
    if (bestAxis < 0 || bestCost >= bounds.area() * count) return leaf(index, first, count);
    const double lo = centreBounds.lo[bestAxis], extent = centreBounds.hi[bestAxis] - lo;
    // A stable partition keeps the scene order inside each side: the tree
    // depends on nothing but the triangles.
    const auto mid = std::stable_partition(order.begin() + first, order.begin() + first + count, [&](std::uint32_t t) {
      return binOf(centres[t][bestAxis], lo, extent) <= bestSplit;
    });
    const std::uint32_t leftCount = static_cast<std::uint32_t>(mid - (order.begin() + first));
    nodes[index].axis = static_cast<std::uint8_t>(bestAxis);
    build(first, leftCount, depth + 1);
    nodes[index].first = static_cast<std::uint32_t>(nodes.size());
    build(first + leftCount, count - leftCount, depth + 1);
  }

  static int binOf(double c, double lo, double extent) {
    return std::min(kBins - 1, static_cast<int>((c - lo) / extent * kBins));
  }

  void leaf(std::uint32_t index, std::uint32_t first, std::uint32_t count) {
    nodes[index].first = first, nodes[index].count = count;
  }
};

// Möller-Trumbore in double: a miss through a shared edge would need the two
// triangles' rounding errors to disagree at ~1e-16, far below the pixel.
bool intersect(const BvhTriangle& tri, const Ray& ray, double tMin, double tMax, Hit& hit) {
  const DVec3 p = glm::cross(ray.direction, tri.e2);
  const double det = glm::dot(tri.e1, p);
  if (det == 0.0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  const DVec3 s = ray.origin - tri.p0;
  const double b1 = glm::dot(s, p) * inv;
  if (b1 < 0.0 || b1 > 1.0) return false;
  const DVec3 q = glm::cross(s, tri.e1);
  const double b2 = glm::dot(ray.direction, q) * inv;
  if (b2 < 0.0 || b1 + b2 > 1.0) return false;
  const double t = glm::dot(tri.e2, q) * inv;
  if (!(t > tMin && t < tMax)) return false;
  hit.t = t, hit.b1 = b1, hit.b2 = b2;
  hit.frontFacing = det > 0.0;  // det = -d . (e1 x e2) > 0: the ray meets the CCW side
  return true;
}

// The slab test; tFar of a box behind the ray or beyond tMax rejects it.
bool hitsBox(const Bvh::Node& n, const DVec3& origin, const DVec3& inv, double tMin, double tMax, double& tNear) {
  const DVec3 t0 = (n.lo - origin) * inv, t1 = (n.hi - origin) * inv;
  const DVec3 a = glm::min(t0, t1), b = glm::max(t0, t1);
  // NaN (0 * inf, a ray in a slab's plane) compares false and leaves the bound as is.
  // The exits are widened by 2 gamma(3) (pbrt-v4, Bounds3::IntersectP):
  // rounding must not lose a hit on the edge of a flat box (coplanar tiles).
  constexpr double widen = 1.0 + 2.0 * (3.0 * 0x1.0p-53) / (1.0 - 3.0 * 0x1.0p-53);
  double lo = tMin, hi = tMax;
  for (int i = 0; i < 3; ++i) {
    if (a[i] > lo) lo = a[i];
    if (b[i] * widen < hi) hi = b[i] * widen;
  }
  tNear = lo;
  return lo <= hi;
}

template <bool AnyHit>
bool traverse(const std::vector<Bvh::Node>& nodes, const std::vector<BvhTriangle>& tris, const Ray& ray, double tMin,
              double tMax, Facing facing, Hit& best) {
  if (nodes.empty()) return false;
  const DVec3 inv(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z);
  std::array<std::uint32_t, 64> stack;
  int top = 0;
  stack[top++] = 0;
  double tNear = 0.0;
  while (top > 0) {
    const Bvh::Node& n = nodes[stack[--top]];
    if (!hitsBox(n, ray.origin, inv, tMin, std::min(tMax, best.t), tNear)) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        Hit h;
        if (!intersect(tris[i], ray, tMin, tMax, h)) continue;
        if (facing == Facing::FrontOnly && !h.frontFacing && !tris[i].twoSided) continue;
        if (AnyHit) return true;
        // Equal distances (a shared edge) go to the lower id, whatever the order of visits.
        if (h.t < best.t || (h.t == best.t && i < best.id)) h.id = i, best = h;
      }
      continue;
    }
    const std::uint32_t nearChild = &n - nodes.data() + 1, farChild = n.first;
    // Visit the child on the ray's near side first (pushed last).
    const bool flip = ray.direction[n.axis] < 0.0;
    stack[top++] = flip ? nearChild : farChild;
    stack[top++] = flip ? farChild : nearChild;
  }
  return best.found();
}

}  // namespace

Bvh::Bvh(const Scene& scene) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Mesh& m = scene.objects[o].mesh;
    const MaterialKind kind = scene.materials[static_cast<std::size_t>(scene.objects[o].material)].kind;
    // Glass is seen from both sides (the 1994 change of medium from behind:
    // eta = ior); the pipeline culls a refracting face seen from behind, one
    // of the approximations the accuracy measure reports.
    const bool twoSided = kind == MaterialKind::Refractive || kind == MaterialKind::Translucent ||
                          kind == MaterialKind::Frosted;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const DVec3 a(m.positions[m.triangles[t][0]]), b(m.positions[m.triangles[t][1]]), c(m.positions[m.triangles[t][2]]);
      tris_.push_back({a, b - a, c - a, static_cast<std::uint32_t>(o), static_cast<std::uint32_t>(t), twoSided});
    }
  }
  if (tris_.empty()) return;
  Builder b{tris_, nodes_, {}, {}, {}};
  for (const BvhTriangle& t : tris_) {
    b.boxes.push_back(boxOf(t));
    b.centres.push_back((b.boxes.back().lo + b.boxes.back().hi) * 0.5);
  }
  b.order.resize(tris_.size());
  for (std::uint32_t i = 0; i < b.order.size(); ++i) b.order[i] = i;
  b.build(0, static_cast<std::uint32_t>(tris_.size()), 0);
  std::vector<BvhTriangle> sorted;
  sorted.reserve(tris_.size());
  for (std::uint32_t i : b.order) sorted.push_back(tris_[i]);
  tris_ = std::move(sorted);
}

Hit Bvh::closest(const Ray& ray, double tMin, double tMax, Facing facing) const {
  Hit best;
  traverse<false>(nodes_, tris_, ray, tMin, tMax, facing, best);
  return best;
}

bool Bvh::occluded(const Ray& ray, double tMin, double tMax) const {
  Hit best;
  return traverse<true>(nodes_, tris_, ray, tMin, tMax, Facing::Both, best);
}

}  // namespace mpr
