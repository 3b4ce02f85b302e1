#include "conformance/buffer_comparison.hpp"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mpr {
namespace {

// A coordinate is exactly representable when it is a multiple of the
// sub-pixel step, 1/256, of moderate size.
bool dyadic(double v) {
  const double s = v * 256.0;
  return std::fabs(v) < 32768.0 && s == std::floor(s);
}

}  // namespace

ConformanceBounds boundsFor(const Script& script) {
  ConformanceBounds b{true, false};
  for (const ScriptCommand& c : script.commands) {
    if (c.kind != ScriptCommand::Kind::Call) continue;
    switch (c.call) {
      case GLCall::Frustum: case GLCall::Perspective: case GLCall::LookAt: case GLCall::Rotatef:
      case GLCall::Rotated:
        b.exactCoordinates = false;
        break;
      case GLCall::Vertex2f: case GLCall::Vertex3f: case GLCall::Vertex4f: case GLCall::Rectf:
      case GLCall::Translatef: case GLCall::Translated: case GLCall::Scalef: case GLCall::Scaled:
      case GLCall::Ortho: case GLCall::LoadMatrixf: case GLCall::LoadMatrixd: case GLCall::MultMatrixf:
      case GLCall::MultMatrixd:
        for (const ScriptArg& a : c.args)
          if (!dyadic(a.number)) b.exactCoordinates = false;
        if (c.call == GLCall::Vertex4f && c.args[3].number != 1.0) b.exactCoordinates = false;
        break;
      case GLCall::Enable:
        if (c.args[0].bits == GL_LIGHTING || c.args[0].bits == GL_FOG) b.litOrFogged = true;
        break;
      default:
        break;
    }
  }
  return b;
}

bool showsColourMaterialBackInBegin(const Script& script) {
  bool twoSide = false, backTracked = false, inBegin = false, colourInBegin = false, backMaterialInBegin = false;
  for (const ScriptCommand& c : script.commands) {
    if (c.kind != ScriptCommand::Kind::Call) continue;
    switch (c.call) {
      case GLCall::LightModeli: case GLCall::LightModelf:
        if (c.args[0].bits == GL_LIGHT_MODEL_TWO_SIDE && c.args[1].number != 0.0) twoSide = true;
        break;
      case GLCall::ColorMaterial:
        if (c.args[0].bits == GL_BACK || c.args[0].bits == GL_FRONT_AND_BACK) backTracked = true;
        break;
      case GLCall::Materialf: case GLCall::Materialfv:
        // glMaterial of the back inside glBegin shows the same saturation
        // (back_material_in_begin.gls)
        if (inBegin && (c.args[0].bits == GL_BACK || c.args[0].bits == GL_FRONT_AND_BACK)) backMaterialInBegin = true;
        break;
      case GLCall::Begin: inBegin = true; break;
      case GLCall::End: inBegin = false; break;
      case GLCall::Color3f: case GLCall::Color4f: case GLCall::Color3ub: case GLCall::Color4ub:
        if (inBegin) colourInBegin = true;
        break;
      default: break;
    }
  }
  return twoSide && ((backTracked && colourInBegin) || backMaterialInBegin);
}

PointAgreement compareBuffers(const BufferSet& m, const BufferSet& g, const ConformanceBounds& bounds,
                              std::size_t keep, const std::vector<DepartureRun>& departures) {
  PointAgreement p;
  p.point = m.point;
  p.color.buffer = "color";
  p.depth.buffer = "depth";
  p.stencil.buffer = "stencil";
  p.color.bound = bounds.colorBound();
  p.depth.bound = bounds.depthBound();
  p.stencil.bound = 0;
  p.stencil.requiredFraction = bounds.stencilFraction();
  const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
  for (BufferAgreement* b : {&p.color, &p.depth, &p.stencil}) {
    b->pixels = n;
    b->strict = bounds.strict;
  }
  // The largest difference of each buffer at pixel i between a and Mesa.
  auto diffs = [&](const BufferSet& a, std::size_t i) {
    int dc = 0;
    for (int c = 0; c < 4; ++c) dc = std::max(dc, std::abs(int(a.color[i * 4 + c]) - int(g.color[i * 4 + c])));
    return std::array<int, 3>{dc, std::abs(static_cast<int>(a.depth[i]) - static_cast<int>(g.depth[i])),
                              std::abs(int(a.stencil[i]) - int(g.stencil[i]))};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const int x = static_cast<int>(i % m.width), y = static_cast<int>(i / m.width);
    int dc = 0;
    for (int c = 0; c < 4; ++c) dc = std::max(dc, std::abs(int(m.color[i * 4 + c]) - int(g.color[i * 4 + c])));
    const int dz = std::abs(static_cast<int>(m.depth[i]) - static_cast<int>(g.depth[i]));
    const int ds = std::abs(int(m.stencil[i]) - int(g.stencil[i]));
    // A pixel out of bound is explained by the first departure whose run
    // brings every buffer of it within the bounds.
    std::string departure;
    if (dc > p.color.bound || dz > p.depth.bound || ds > p.stencil.bound)
      for (const DepartureRun& r : departures) {
        const bool ok = r.colourWhereDepthAgrees
                            ? dz <= p.depth.bound && ds <= p.stencil.bound
                            : [&] {
                                const std::array<int, 3> d = diffs(*r.buffers, i);
                                return d[0] <= p.color.bound && d[1] <= p.depth.bound && d[2] <= p.stencil.bound;
                              }();
        if (ok) {
          departure = r.name;
          ++p.departures[r.name];
          break;
        }
      }
    auto account = [&](BufferAgreement& b, int d, std::array<int, 4> mv, std::array<int, 4> gv) {
      if (d == 0) ++b.agree;
      if (d <= b.bound) ++b.withinBound;
      else if (!departure.empty()) ++b.explained;
      b.maxDiff = std::max(b.maxDiff, d);
      if (d != 0 && b.first.size() < keep) b.first.push_back({x, y, mv, gv, d > b.bound ? departure : ""});
    };
    account(p.color, dc,
            {m.color[i * 4], m.color[i * 4 + 1], m.color[i * 4 + 2], m.color[i * 4 + 3]},
            {g.color[i * 4], g.color[i * 4 + 1], g.color[i * 4 + 2], g.color[i * 4 + 3]});
    account(p.depth, dz, {static_cast<int>(m.depth[i]), 0, 0, 0}, {static_cast<int>(g.depth[i]), 0, 0, 0});
    account(p.stencil, ds, {m.stencil[i], 0, 0, 0}, {g.stencil[i], 0, 0, 0});
  }
  return p;
}

}  // namespace mpr
