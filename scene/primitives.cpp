#include "scene/primitives.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {
namespace {

constexpr float kPi = 3.14159265358979323846f;

// Adds a planar polygon with one normal for all its corners.
void addFlatFace(Mesh& m, const std::vector<Vec3>& corners, const Vec3& normal) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  std::vector<std::uint32_t> face;
  for (const Vec3& c : corners) {
    face.push_back(static_cast<std::uint32_t>(m.positions.size()));
    m.positions.push_back(c);
    m.normals.push_back(normal);
  }
  for (std::uint32_t i = 1; i + 1 < corners.size(); ++i) m.triangles.push_back({base, base + i, base + i + 1});
  m.faces.push_back(std::move(face));
}

// One coordinate of the lattice of a subdivided unit primitive: every face
// computes a shared edge's points by this one expression, so they are bit
// for bit the same on both faces (meshes weld closed, no cracks between
// faces). d = 1 gives exactly -0.5 and 0.5.
float lattice(int k, int d) { return -0.5f + static_cast<float>(k) / static_cast<float>(d); }

// A flat side of a unit primitive as a d x d grid of cells sharing their
// corners. `origin` is a lattice point, `u` and `v` unit lattice steps with
// u x v along `normal` (counter-clockwise seen from outside). The cells split
// along the diagonal from their first corner, as addFlatFace splits a quad;
// the side stays one polygon in `faces` (the planar-face checks and the
// specular faces see the side, not its cells).
void addGridFace(Mesh& m, glm::ivec3 origin, glm::ivec3 u, glm::ivec3 v, const Vec3& normal, int d) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  for (int j = 0; j <= d; ++j)
    for (int i = 0; i <= d; ++i) {
      const glm::ivec3 q = origin + i * u + j * v;
      m.positions.emplace_back(lattice(q.x, d), lattice(q.y, d), lattice(q.z, d));
      m.normals.push_back(normal);
    }
  const auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(j * (d + 1) + i); };
  for (int j = 0; j < d; ++j)
    for (int i = 0; i < d; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  m.faces.push_back({at(0, 0), at(d, 0), at(d, d), at(0, d)});
}

}  // namespace

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const SceneObject& o : objects) n += o.mesh.triangles.size();
  return n;
}

Mesh makeBox(int divisions) {
  Mesh m;
  if (divisions > 1) {
    // Lattice coordinates 0..d; each side as makeBox's corners below order it.
    const int d = divisions;
    addGridFace(m, {0, 0, d}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, d);
    addGridFace(m, {d, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, -1}, d);
    addGridFace(m, {d, 0, d}, {0, 0, -1}, {0, 1, 0}, {1, 0, 0}, d);
    addGridFace(m, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {-1, 0, 0}, d);
    addGridFace(m, {0, d, d}, {1, 0, 0}, {0, 0, -1}, {0, 1, 0}, d);
    addGridFace(m, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}, d);
    return m;
  }
  const float h = 0.5f;
  addFlatFace(m, {{-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}}, {0, 0, 1});
  addFlatFace(m, {{h, -h, -h}, {-h, -h, -h}, {-h, h, -h}, {h, h, -h}}, {0, 0, -1});
  addFlatFace(m, {{h, -h, h}, {h, -h, -h}, {h, h, -h}, {h, h, h}}, {1, 0, 0});
  addFlatFace(m, {{-h, -h, -h}, {-h, -h, h}, {-h, h, h}, {-h, h, -h}}, {-1, 0, 0});
  addFlatFace(m, {{-h, h, h}, {h, h, h}, {h, h, -h}, {-h, h, -h}}, {0, 1, 0});
  addFlatFace(m, {{-h, -h, -h}, {h, -h, -h}, {h, -h, h}, {-h, -h, h}}, {0, -1, 0});
  return m;
}

Mesh makeSphere(int slices, int stacks) {
  Mesh m;
  for (int j = 0; j <= stacks; ++j) {
    const float v = static_cast<float>(j) / static_cast<float>(stacks);
    const float phi = v * kPi;
    for (int i = 0; i <= slices; ++i) {
      const float theta = static_cast<float>(i) / static_cast<float>(slices) * 2.0f * kPi;
      Vec3 p(std::sin(phi) * std::cos(theta), std::cos(phi), -std::sin(phi) * std::sin(theta));
      // The poles and the seam repeat exactly the same point, so the mesh
      // welds closed (shadow volumes need a closed silhouette).
      if (j == 0 || j == stacks) p = Vec3(0.0f, j == 0 ? 1.0f : -1.0f, 0.0f);
      else if (i == slices) p = m.positions[m.positions.size() - static_cast<std::size_t>(slices)];
      m.positions.push_back(p);
      m.normals.push_back(p);
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(stacks); ++j)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i) {
      const std::uint32_t a = j * row + i, b = a + row, c = b + 1, d = a + 1;
      if (j != 0) m.triangles.push_back({a, b, d});
      if (j + 1 != static_cast<std::uint32_t>(stacks)) m.triangles.push_back({d, b, c});
    }
  for (const auto& t : m.triangles) m.faces.push_back({t[0], t[1], t[2]});
  return m;
}

Mesh makeCylinder(int slices) {
  Mesh m;
  for (int i = 0; i < slices; ++i) {
    const float a0 = static_cast<float>(i) / static_cast<float>(slices) * 2.0f * kPi;
    // The last side ends exactly where the first begins (a closed mesh).
    const float a1 = i + 1 == slices ? 0.0f : static_cast<float>(i + 1) / static_cast<float>(slices) * 2.0f * kPi;
    const Vec3 p0(std::cos(a0), 0, -std::sin(a0)), p1(std::cos(a1), 0, -std::sin(a1));
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const Vec3& p : {p0, p1}) {
      m.positions.push_back(p + Vec3(0, -0.5f, 0));
      m.normals.push_back(p);
      m.positions.push_back(p + Vec3(0, 0.5f, 0));
      m.normals.push_back(p);
    }
    // base: p0 bottom, p0 top, p1 bottom, p1 top
    m.triangles.push_back({base, base + 2, base + 3});
    m.triangles.push_back({base, base + 3, base + 1});
    m.faces.push_back({base, base + 2, base + 3, base + 1});
  }
  std::vector<Vec3> top, bottom;
  for (int i = 0; i < slices; ++i) {
    const float a = static_cast<float>(i) / static_cast<float>(slices) * 2.0f * kPi;
    top.emplace_back(std::cos(a), 0.5f, -std::sin(a));
    bottom.insert(bottom.begin(), Vec3(std::cos(a), -0.5f, -std::sin(a)));
  }
  addFlatFace(m, top, {0, 1, 0});
  addFlatFace(m, bottom, {0, -1, 0});
  return m;
}

Mesh makeQuad(int divisions) {
  Mesh m;
  if (divisions > 1) {
    // The z = 0 slice of the lattice: the plane through its middle.
    const int d = divisions;
    const auto base = m.positions.size();
    addGridFace(m, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, d);
    for (std::size_t i = base; i < m.positions.size(); ++i) m.positions[i].z = 0.0f;
    return m;
  }
  addFlatFace(m, {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}}, {0, 0, 1});
  return m;
}

Mesh makePlane(int divisions) {
  Mesh m;
  const float step = 1.0f / static_cast<float>(divisions);
  for (int j = 0; j < divisions; ++j)
    for (int i = 0; i < divisions; ++i) {
      const float x0 = -0.5f + static_cast<float>(i) * step, z0 = 0.5f - static_cast<float>(j) * step;
      addFlatFace(m, {{x0, 0, z0}, {x0 + step, 0, z0}, {x0 + step, 0, z0 - step}, {x0, 0, z0 - step}}, {0, 1, 0});
    }
  // The plane is one polygon for the planar-face checks and the specular
  // faces (a mirror plane is one mirror, not a mirror per cell): the outer
  // corners of the corner cells.
  const auto corner = [&](int i, int j, std::uint32_t k) {
    return static_cast<std::uint32_t>(4 * (j * divisions + i)) + k;
  };
  const int e = divisions - 1;
  m.faces = {{corner(0, 0, 0), corner(e, 0, 1), corner(e, e, 2), corner(0, e, 3)}};
  return m;
}

void transformMesh(Mesh& mesh, const Mat4& m) {
  const glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(m)));
  for (Vec3& p : mesh.positions) p = Vec3(m * Vec4(p, 1.0f));
  for (Vec3& v : mesh.normals) {
    v = n * v;
    const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (len > 0.0f) v /= len;
  }
  // A mirroring transform flips the winding.
  if (glm::determinant(glm::mat3(m)) < 0.0f) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    for (auto& f : mesh.faces) std::reverse(f.begin() + 1, f.end());
  }
}

}  // namespace mpr
