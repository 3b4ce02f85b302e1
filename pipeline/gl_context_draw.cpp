// GLContext: glBegin/glEnd, vertex processing, primitive assembly, clipping,
// culling, rasterization and the hand-over to the per-fragment operations.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "pipeline/gl_context.hpp"
#include "pipeline/transforms.hpp"
#include "raster/triangle_rasterizer.hpp"

namespace mpr {
namespace {

bool finite4(const Vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

Vec4 clampColor(const Vec4& c) { return glm::clamp(c, Vec4(0.0f), Vec4(1.0f)); }

}  // namespace

void GLContext::begin(GLenumValue mode) {
  if (inBegin_) return setError(GL_INVALID_OPERATION);
  switch (mode) {
    case GL_TRIANGLES: primitive_ = PrimitiveType::Triangles; break;
    case GL_TRIANGLE_STRIP: primitive_ = PrimitiveType::TriangleStrip; break;
    case GL_TRIANGLE_FAN: primitive_ = PrimitiveType::TriangleFan; break;
    case GL_QUADS: primitive_ = PrimitiveType::Quads; break;
    case GL_QUAD_STRIP: primitive_ = PrimitiveType::QuadStrip; break;
    case GL_POLYGON: primitive_ = PrimitiveType::Polygon; break;
    default: return setError(GL_INVALID_ENUM);
  }
  inBegin_ = true;
  vertices_.clear();
}

void GLContext::vertex4f(float x, float y, float z, float w) {
  if (!inBegin_) return;  // outside glBegin/glEnd GL leaves the result undefined; ignore
  vertices_.push_back({Vec4(x, y, z, w), currentColor_, currentNormal_});
}

void GLContext::rectf(float x1, float y1, float x2, float y2) {
  if (!checkOutsideBeginEnd()) return;
  // GL 1.1 section 2.9: exactly glBegin(GL_POLYGON) with four vertices.
  begin(GL_POLYGON);
  vertex4f(x1, y1, 0, 1);
  vertex4f(x2, y1, 0, 1);
  vertex4f(x2, y2, 0, 1);
  vertex4f(x1, y2, 0, 1);
  end();
}

ClipVertex GLContext::processVertex(const Vertex& v) const {
  ClipVertex out;
  // Position through the combined matrix, as Mesa's fixed-function program.
  out.clip = mvp_ * v.object;
  const bool needEye = lightingEnabled_ || fog_.enabled;
  const Vec4 eye = needEye ? modelview_.top() * v.object : Vec4(0.0f);

  Vec4 front, back;
  if (lightingEnabled_) {
    LightingState s = lighting_;
    if (colorMaterialEnabled_) {
      // The vertex's own colour feeds the tracked material parameter.
      const Vec4 c = v.color;
      for (int side = 0; side < 2; ++side) {
        if ((side == 0 && colorMaterialFace_ == GL_BACK) || (side == 1 && colorMaterialFace_ == GL_FRONT))
          continue;
        Material& m = s.material[side];
        switch (colorMaterialMode_) {
          case GL_EMISSION: m.emission = c; break;
          case GL_AMBIENT: m.ambient = c; break;
          case GL_DIFFUSE: m.diffuse = c; break;
          case GL_SPECULAR: m.specular = c; break;
          default: m.ambient = m.diffuse = c; break;
        }
      }
    }
    Vec3 n = normalMatrix_ * v.normal;
    if (normalize_) {
      const float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
      if (len > 0.0f) n = n / len;
    }
    front = lightVertex(s, eye, n, false);
    back = lighting_.model.twoSide ? lightVertex(s, eye, n, true) : front;
  } else {
    front = back = clampColor(v.color);
  }
  for (int i = 0; i < 4; ++i) {
    out.attr[i] = front[i];
    out.attr[4 + i] = back[i];
  }
  // Fog coordinate: the eye-space distance |z_eye|.
  const float fogCoord = std::fabs(eye.z);
  out.attr[8] = fog_.enabled && !fog_.perFragment ? fogFactor(fog_, fogCoord) : fogCoord;
  return out;
}

void GLContext::end() {
  if (!inBegin_) return setError(GL_INVALID_OPERATION);
  inBegin_ = false;

  mvp_ = multiply(projection_.top(), modelview_.top());
  normalMatrix_ = glm::transpose(glm::inverse(glm::mat3(modelview_.top())));
  clipPlanesClip_ = viewVolumePlanes();
  const Mat4 projInverse = glm::inverse(projection_.top());
  for (int i = 0; i < 6; ++i)
    if (clipPlaneEnabled_[i]) clipPlanesClip_.push_back(clipPlanesEye_[i] * projInverse);

  const std::vector<AssembledTriangle> tris = assembleTriangles(primitive_, static_cast<std::uint32_t>(vertices_.size()));
  if (tris.empty()) return;
  std::vector<ClipVertex> processed;
  processed.reserve(vertices_.size());
  for (const Vertex& v : vertices_) processed.push_back(processVertex(v));

  for (const AssembledTriangle& t : tris) {
    std::array<ClipVertex, 3> tri = {processed[t.v[0]], processed[t.v[1]], processed[t.v[2]]};
    if (flatShading_)
      for (ClipVertex& cv : tri)
        for (int i = 0; i < 8; ++i) cv.attr[i] = processed[t.provoking].attr[i];
    drawTriangle(tri);
  }
}

void GLContext::drawTriangle(const std::array<ClipVertex, 3>& tri) {
  ++counters_.triangles;
  // A vertex that is not finite drops its primitive and touches nothing else.
  for (const ClipVertex& v : tri) {
    if (!finite4(v.clip)) return;
    for (float a : v.attr)
      if (!std::isfinite(a)) return;
  }
  std::vector<ClipVertex> poly(tri.begin(), tri.end());
  poly = clipPolygon(std::move(poly), clipPlanesClip_);
  if (poly.size() < 3) return;
  for (const ClipVertex& v : poly)
    if (!(v.clip.w > 0.0f)) return;  // only the point (0,0,0,0) survives clipping with w <= 0
  ++counters_.trianglesDrawn;
  for (size_t i = 1; i + 1 < poly.size(); ++i) rasterizeClippedTriangle(poly[0], poly[i], poly[i + 1]);
}

void GLContext::rasterizeClippedTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
  const ClipVertex* v[3] = {&a, &b, &c};
  std::array<SnappedVertex, 3> snapped;
  double zWin[3], invW[3], xWin[3], yWin[3];
  // Viewport depth transform: z_w = z_ndc * (f - n) / 2 + (n + f) / 2.
  const float zScale = static_cast<float>((depthFar_ - depthNear_) / 2.0);
  const float zTrans = static_cast<float>((depthNear_ + depthFar_) / 2.0);
  for (int i = 0; i < 3; ++i) {
    const float iw = 1.0f / v[i]->clip.w;
    const float xw = v[i]->clip.x * iw * vpScaleX_ + vpTransX_;
    const float yw = v[i]->clip.y * iw * vpScaleY_ + vpTransY_;
    zWin[i] = static_cast<double>(v[i]->clip.z * iw * zScale + zTrans);
    invW[i] = static_cast<double>(iw);
    xWin[i] = xw;
    yWin[i] = yw;
    snapped[i] = snapVertex(xw, yw);
  }
  const std::int64_t area = signedArea2(snapped[0], snapped[1], snapped[2]);
  if (area == 0) return;
  const bool ccw = area > 0;
  const bool front = (frontFace_ == GL_CCW) == ccw;
  if (cullEnabled_ && (cullMode_ == GL_FRONT_AND_BACK || (cullMode_ == GL_FRONT) == front)) return;
  const int colorOffset = (front || !(lightingEnabled_ && lighting_.model.twoSide)) ? 0 : 4;

  const PixelRect region = drawRegion();
  if (region.empty()) return;
  const PixelBounds bounds{region.x0, region.y0, region.x1, region.y1};
  // Coverage is decided on the snapped vertices; attributes are interpolated
  // on the unsnapped window positions, as llvmpipe sets up its planes, so
  // that snapping (up to 1/512 pixel) does not tilt a steep depth plane.
  const double ex1 = xWin[1] - xWin[0], ey1 = yWin[1] - yWin[0];
  const double ex2 = xWin[2] - xWin[0], ey2 = yWin[2] - yWin[0];
  const double exactArea = ex1 * ey2 - ex2 * ey1;
  const bool useSnapped = !(std::fabs(exactArea) > 0.0);  // degenerate before snapping
  const double snappedArea = static_cast<double>(area > 0 ? area : -area);  // the weights' sum
  const float depthMaxF = static_cast<float>(fb_.profile().depthMax());
  const bool needColor = frag_.colorMask[0] || frag_.colorMask[1] || frag_.colorMask[2] ||
                         frag_.colorMask[3] || frag_.alpha.enabled;
  const bool needDepth = frag_.depth.enabled;

  rasterizeTriangle(snapped, bounds, [&](int x, int y, std::int64_t w0, std::int64_t w1, std::int64_t w2) {
    // Barycentric weights of the pixel centre.
    double b0, b1, b2;
    if (useSnapped) {
      b0 = static_cast<double>(w0) / snappedArea;
      b1 = static_cast<double>(w1) / snappedArea;
      b2 = static_cast<double>(w2) / snappedArea;
    } else {
      const double px = x + 0.5 - xWin[0], py = y + 0.5 - yWin[0];
      b1 = (px * ey2 - py * ex2) / exactArea;
      b2 = (py * ex1 - px * ey1) / exactArea;
      b0 = 1.0 - b1 - b2;
    }
    Fragment f{x, y, 0, Rgba8{0, 0, 0, 0}, 0.0f};
    if (needDepth) {
      // Depth is linear in window space; quantised to the profile's width as
      // llvmpipe converts to a unorm buffer: the float z times the float
      // maximum, a single-precision product, rounded to nearest even.
      // (llvmpipe evaluates the depth plane in single precision, we in double:
      // on sloped planes the two may differ by a unit or so.)
      const double z = std::clamp(zWin[0] + b1 * (zWin[1] - zWin[0]) + b2 * (zWin[2] - zWin[0]), 0.0, 1.0);
      const float product = static_cast<float>(z) * depthMaxF;
      f.depth = static_cast<std::uint32_t>(std::nearbyint(product));
    }
    if (needColor) {
      // Perspective-correct: interpolate attr/w and 1/w.
      const double p0 = b0 * invW[0], p1 = b1 * invW[1], p2 = b2 * invW[2];
      const double inv = 1.0 / (p0 + p1 + p2);
      auto interp = [&](int i) {
        return static_cast<float>((p0 * v[0]->attr[i] + p1 * v[1]->attr[i] + p2 * v[2]->attr[i]) * inv);
      };
      Vec4 color(interp(colorOffset), interp(colorOffset + 1), interp(colorOffset + 2), interp(colorOffset + 3));
      if (fog_.enabled) {
        const float t = interp(8);
        const float factor = fog_.perFragment ? fogFactor(fog_, t) : std::clamp(t, 0.0f, 1.0f);
        color = applyFog(fog_, factor, color);
      }
      color = clampColor(color);
      f.color = {floatToUnorm8(color.r), floatToUnorm8(color.g), floatToUnorm8(color.b), floatToUnorm8(color.a)};
      f.alpha = color.a;
    }
    ++counters_.fragmentsTested;
    if (fragmentObserver) {
      FragmentEvent ev{x, y, fb_.stencil(x, y), 0, fb_.depth(x, y), f.depth, FragmentFate::Written, {}};
      ev.fate = processFragment(frag_, fb_, f);
      ev.stencilAfter = fb_.stencil(x, y);
      ev.colorAfter = fb_.color(x, y);
      if (ev.fate == FragmentFate::Written) ++counters_.fragmentsWritten;
      fragmentObserver(ev);
      return;
    }
    if (processFragment(frag_, fb_, f) == FragmentFate::Written) ++counters_.fragmentsWritten;
  });
}

}  // namespace mpr
