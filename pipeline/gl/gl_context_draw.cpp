// GLContext: glBegin/glEnd, vertex processing, primitive assembly, clipping,
// culling, rasterization and the hand-over to the per-fragment operations.
#include <GL/gl.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "pipeline/gl/gl_context.hpp"
#include "raster/llvmpipe_depth.hpp"
#include "raster/llvmpipe_math.hpp"
#include "raster/llvmpipe_row_spans.hpp"
#include "raster/llvmpipe_tile_raster.hpp"
#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "raster/span_shading.hpp"
#include "util/transforms.hpp"
#include "raster/fixed_point.hpp"
#include "raster/triangle_rasterizer.hpp"
#include "util/cpu_dispatch.hpp"

namespace mpr {
namespace {

bool finite4(const Vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// The coverage vertex of a triangle drawn without the window map: its
// window position as llvmpipe computes and snaps it (fused, on OSMesa's
// flipped rows); false where that position is not finite.
inline bool snapLikeLlvmpipeRaster(const ClipVertex& v, const WindowTransform& window, int fbHeight,
                                   SnappedVertex& out) {
  const LlWindow l = llvmpipeWindow(v.clip, window);
  if (!std::isfinite(l.x) || !std::isfinite(l.y)) return false;
  out = {snapToSubpixel(l.x), (static_cast<std::int64_t>(fbHeight) - 1) * kSubpixelOne - snapToSubpixel(l.y)};
  return true;
}

// Whether signedArea2 of snapped positions this close to the origin is
// exact: coordinates below 2^30 keep each product below 2^62.
inline bool areaCannotOverflow(const SnappedVertex& v) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  return v.x > -kLimit && v.x < kLimit && v.y > -kLimit && v.y < kLimit;
}

// Whether the fragments' colour is read: a colour channel is written, or
// the alpha test looks at alpha.
bool needsColor(const FragmentState& s) {
  return s.colorMask[0] || s.colorMask[1] || s.colorMask[2] || s.colorMask[3] || s.alpha.enabled;
}

// glm::clamp(c, 0, 1) written out per component (glm's min and max are
// std::min and std::max, NaN kept alike); glm's generic form is not inlined.
[[gnu::always_inline]] inline Vec4 clampColor(const Vec4& c) {
  auto clamp01 = [](float v) { return std::min(std::max(v, 0.0f), 1.0f); };
  return Vec4(clamp01(c.x), clamp01(c.y), clamp01(c.z), clamp01(c.w));
}

// vbo_copy_vertices: how many of the `count` vertices of a primitive cut by
// the vbo begin the next piece (for a fan or a polygon the first and the
// last, for the others the last ones).
std::size_t carriedVertexCount(PrimitiveType type, std::size_t count) {
  switch (type) {
    case PrimitiveType::Triangles: return count % 3;
    case PrimitiveType::Quads: return count % 4;
    case PrimitiveType::TriangleFan:
    case PrimitiveType::Polygon: return std::min<std::size_t>(count, 2);
    default: return count <= 1 ? count : 2 + count % 2;  // strips
  }
}

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
  analyseMatrices(true, true);  // vbo_exec_Begin validates the state (_mesa_update_state)
  // Only another GL_QUADS block can join the open quad draw.
  if (primitive_ != PrimitiveType::Quads) closeQuadDraw();
  // vbo_exec_Begin: attributes set since the last flush but no vertex (all
  // outside glBegin/glEnd) are not kept in the format.
  if (vboSize_[kVboPosition] == 0) copyAndResetFormat();
  inBegin_ = true;
  vboStored_ = true;
  blockWraps_.clear();
  pieceVertexCount_ = 0;
  vertices_.clear();
  blockMaterials_.assign(1, lighting_.material);
  blockMaterialUsed_ = false;
}

void GLContext::vertex4f(float x, float y, float z, float w, int size) {
  if (!inBegin_) return;  // outside glBegin/glEnd GL leaves the result undefined; ignore
  vboAttribute(kVboPosition, size);
  ++vboVertexCount_;
  ++pieceVertexCount_;
  vertices_.push_back({Vec4(x, y, z, w), currentColor_, currentNormal_,
                       static_cast<std::uint32_t>(blockMaterials_.size() - 1)});
  blockMaterialUsed_ = true;
}

void GLContext::settle() const {
  // The context is never const in storage; a reader through a const
  // reference expects what GL would show after a flush.
  if (quadDraw_.open) const_cast<GLContext*>(this)->flushVertices();
  drain();
}

void GLContext::drain() const {
  if (!rowQueue) return;
  rowQueue->wait();
  // Sums: the same whichever thread counted what.
  auto* self = const_cast<GLContext*>(this);
  for (RowTally& t : self->rowTallies) {
    self->counters_.fragmentsTested += t.tally.tested;
    self->counters_.fragmentsWritten += t.tally.written;
    t.tally = {};
  }
}

void GLContext::vboAttribute(int slot, int size) {
  auto& current = vboSize_[static_cast<std::size_t>(slot)];
  if (size <= current) return;  // the same size or smaller: filled in, no wrap
  const bool first = current == 0;
  const std::uint8_t shininessBefore = shininessVarying();  // the format the stored vertices are drawn with
  const bool colorBefore = vboSize_[kVboColor] != 0;
  current = static_cast<std::uint8_t>(size);
  if (inBegin_) {
    // vbo_exec_wrap_buffers: what the buffer holds is drawn, this block is
    // cut here (end() draws the pieces).
    if (!vertices_.empty() || vboVertexCount_ > 0) blockWraps_.push_back({vertices_.size(), shininessBefore, colorBefore});
    // The new buffer starts with the vertices carried over (they count
    // towards the heuristic below: glBegin with one vertex, a wrap, eight
    // more and an attribute outside glBegin/glEnd is a reset).
    pieceVertexCount_ = carriedVertexCount(primitive_, pieceVertexCount_);
    vboVertexCount_ = pieceVertexCount_;
    return;
  } else if (vboVertexCount_ > 0) {
    closeQuadDraw();
    // vbo_exec_wrap_upgrade_vertex's heuristic: an attribute first seen
    // outside glBegin/glEnd after more than 8 vertices starts a new format.
    if (first && vboVertexCount_ > 8) {
      copyAndResetFormat();
      current = static_cast<std::uint8_t>(size);
    }
  }
  vboVertexCount_ = 0;
}

void GLContext::flushVertices() {
  // FLUSH_VERTICES: the stored vertices are drawn and, after a glBegin, the
  // vbo's vertex format starts empty (vbo_exec_FlushVertices_internal,
  // vbo_reset_all_attr).
  closeQuadDraw();
  if (vboStored_) copyAndResetFormat();
  vboStored_ = false;
  vboVertexCount_ = 0;
}

void GLContext::closeQuadDraw() {
  if (!quadDraw_.open) return;
  quadDraw_.open = false;
  std::vector<ClipVertex> waiting;
  waiting.swap(quadDraw_.waiting);
  // Drawn with its own vertex format; the piece end() is handing on keeps its.
  const bool pieceColorVarying = pieceColorVarying_;
  pieceColorVarying_ = quadDraw_.colorVarying;
  if (!quadDraw_.clipped && !waiting.empty()) drawProcessed(PrimitiveType::Quads, waiting, false);
  pieceColorVarying_ = pieceColorVarying;
}

void GLContext::rectf(float x1, float y1, float x2, float y2) {
  // A glBegin(GL_QUADS) block of its own (it may join the open quad draw).
  if (inBegin_) return setError(GL_INVALID_OPERATION);
  // GL 1.1 section 2.9 describes glBegin(GL_POLYGON) with these four
  // vertices; Mesa (main/draw.c _mesa_Rectf) issues GL_QUADS, which covers
  // the same pixels but is set up as triangles (0, 1, 2), (0, 2, 3) rather
  // than (1, 2, 0), (2, 3, 0): llvmpipe's depths of a tilted rectangle follow
  // that order. The four vertices share one colour, so the provoking vertex
  // does not matter.
  begin(GL_QUADS);
  vertex4f(x1, y1, 0, 1, 2);  // glVertex2f, as _mesa_Rectf calls it
  vertex4f(x2, y1, 0, 1, 2);
  vertex4f(x2, y2, 0, 1, 2);
  vertex4f(x1, y2, 0, 1, 2);
  end();
}

MPR_CPU_CLONES ClipVertex GLContext::processVertex(const Vertex& v, LightingState& s) const {
  ClipVertex out;
  // Position through the combined matrix, as Mesa's fixed-function program
  // computes it on llvmpipe (measured against llvmpipe's depths).
  const Vec4& o = v.object;
  out.clip = mesaTransformPoint(mvp_, o);
  const bool needEye = lightingEnabled_ || fog_.enabled;
  // The eye position as the program's get_eye_position computes it.
  const Mat4& mv = modelview_.top();
  const Vec4 eye = needEye ? mesaTransformPoint(mv, o) : Vec4(0.0f);

  Vec4 front, back;
  if (lightingEnabled_) {
    s.material = blockMaterials_[v.material];
    if (colorMaterialEnabled_ && vboSize_[kVboColor] != 0) {
      // The vertex's own colour feeds the tracked material parameter where
      // the colour varies in the draw (a glColor since the vbo's format was
      // last reset); otherwise Mesa's fixed-function program reads the
      // material state, which enabling GL_COLOR_MATERIAL set from the
      // colour and a held glMaterial may have set back (copyToCurrent).
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
    // emit_matrix_transform_vec3: component i is DP3(normal, row i of the
    // normal matrix).
    // In object space (LightingState::objectSpace) the program takes the
    // normal as given (times the normal scale, 1 for a length-preserving
    // modelview).
    const glm::mat3 rows = glm::transpose(normalMatrix_);
    Vec3 n = s.objectSpace ? v.normal
                           : Vec3(llvmpipeDot3(v.normal, rows[0]), llvmpipeDot3(v.normal, rows[1]),
                                  llvmpipeDot3(v.normal, rows[2]));
    if (normalize_) {
      // emit_normalize_vec3: DP3, RSQ (a square root and a division), MUL.
      const float lengthSquared = llvmpipeDot3(n, n);
      if (lengthSquared > 0.0f) n = n * (1.0f / std::sqrt(lengthSquared));
    }
    const Vec4 lit = (departures_ & kLightingUndividedEye) ? Vec4(Vec3(eye), 1.0f) : eye;
    front = lightVertex(s, lit, n, false);
    back = lighting_.model.twoSide ? lightVertex(s, lit, n, true) : front;
  } else {
    front = back = clampColor(v.color);
  }
  for (int i = 0; i < 4; ++i) {
    out.attr[i] = front[i];
    out.attr[4 + i] = back[i];
  }
  // Fog coordinate: the eye-space distance |z_eye| (build_fog,
  // FDM_EYE_PLANE_ABS): the z of the eye position where the lighting code
  // computed it (a positional light, or a local viewer with a shininess
  // active), else its own DP4 of the modelview's third row, summed from the
  // last channel (nir_lower_alu_to_scalar).
  bool eyeComputed = false;
  if (lightingEnabled_) {
    for (const LightSource& l : s.lights) eyeComputed = eyeComputed || (l.enabled && l.position.w != 0.0f);
    eyeComputed = eyeComputed || (s.model.localViewer && !s.shininessKeyZero);
  }
  const float eyeZ = eyeComputed ? eye.z : ((mv[3][2] * o.w + mv[2][2] * o.z) + mv[1][2] * o.y) + mv[0][2] * o.x;
  const float fogCoord = std::fabs(eyeZ);
  out.attr[8] = fog_.enabled && !fog_.perFragment ? fogFactor(fog_, fogCoord) : fogCoord;
  return out;
}

void GLContext::end() {
  if (!inBegin_) return setError(GL_INVALID_OPERATION);
  inBegin_ = false;

  mvp_ = multiply(projection_.top(), modelview_.top());
  // GL 1.1 section 2.10.3: normals by the inverse transpose of the
  // modelview's upper 3x3. Mesa's fixed-function program takes the upper 3x3
  // of the 4x4 inverse instead (ffvertex_prog.c, STATE_MODELVIEW_MATRIX_INVTRANS),
  // the same matrix for an affine modelview, so MPR takes Mesa's, its
  // roundings included (a rotation's inverse is its transpose, exactly:
  // m_matrix.c invert_matrix_3d); not for a projective one (the
  // projective_normal_matrix departure).
  const Mat4& mv = modelview_.top();
  const bool affine = mv[0][3] == 0.0f && mv[1][3] == 0.0f && mv[2][3] == 0.0f;
  normalMatrix_ = (affine || (departures_ & kProjectiveNormalMatrix))
                      ? glm::transpose(glm::mat3(modelview_.mesaTop().inverse))
                      : glm::transpose(glm::inverse(glm::mat3(mv)));
  clipPlanesClip_ = viewVolumePlanes();
  // _mesa_update_clip_plane: the eye plane by the projection's inverse as
  // Mesa keeps it (the clip-space planes st_atom_clip.c hands the draw module).
  const Mat4& projInverse = projection_.mesaTop().inverse;  // analysed at glBegin
  for (int i = 0; i < 6; ++i)
    if (clipPlaneEnabled_[i]) clipPlanesClip_.push_back(mesaTransformRowVector(clipPlanesEye_[i], projInverse));
  userPlanesClip_.assign(clipPlanesClip_.begin() + 6, clipPlanesClip_.end());
  if (windowMap_) {
    // The end-of-pipeline map: what lands in the viewport is |u| <= q and
    // |v| <= q (so q >= 0), which is linear in clip coordinates (u w is
    // M[0] . (x, y, w)): the view volume's four sides are replaced by these,
    // so the clipper keeps exactly what the map puts on the screen.
    const glm::mat3& m = *windowMap_;
    const Vec4 u(m[0][0], m[0][1], 0.0f, m[0][2]), v(m[1][0], m[1][1], 0.0f, m[1][2]),
        q(m[2][0], m[2][1], 0.0f, m[2][2]);
    clipPlanesClip_[2] = q + u;
    clipPlanesClip_[3] = q - u;
    clipPlanesClip_[4] = q + v;
    clipPlanesClip_[5] = q - v;
  }

  // The vbo cut the block where an attribute joined its vertex format
  // (vboAttribute): the vertices stored so far are drawn, and the vertices
  // of the unfinished primitive begin the next piece (vbo_copy_vertices).
  // Each piece is a draw of its own with the fixed-function program its
  // vertex format selects, and a vertex carried over is lit again by it.
  struct Piece {
    std::size_t end;      // vertices_ index where the piece stops
    bool shininessZero;   // Mesa's material_shininess_is_zero for its draw
    bool colorVarying;    // the colour is in its vertex format
  };
  std::vector<Piece> pieces;
  for (const BlockWrap& w : blockWraps_)
    pieces.push_back({w.vertex, shininessKeyZero(w.shininessVarying), w.colorVarying});
  pieces.push_back({vertices_.size(), shininessKeyZero(shininessVarying()), vboSize_[kVboColor] != 0});
  blockWraps_.clear();
  // The lighting state every vertex of a draw shares, copied once (it is a
  // kilobyte); each vertex sets its own materials in it.
  LightingState vertexLighting;
  if (lightingEnabled_) {
    vertexLighting = lighting_;
    // On the flags analysed at glBegin (lighting_object_space.gls).
    if (mesaLightsInObjectSpace(lighting_, modelview_.mesaTop().flags))
      toObjectSpace(vertexLighting, modelview_.top(), modelview_.mesaTop().inverse);
  }
  // The first `count` of `indices` (vertices_ indices; all of vertices_
  // when null), lit by the program a piece's draw selects.
  auto processPiece = [&](const std::size_t* indices, std::size_t count, bool shininessZero) {
    vertexLighting.shininessKeyZero = shininessZero;
    vertexLighting.mesaShininess0Attenuated = shininessZero && (departures_ & kShininess0Attenuated);
    std::vector<ClipVertex> processed;
    processed.reserve(count);
    // Within a piece processVertex depends on the vertex alone (the
    // matrices, lights and program are the piece's): a vertex the block
    // repeats (a mesh's triangles share theirs; three in four of the
    // bathroom trace's vertices repeat one of their block) takes the
    // result of its first processing, byte for byte.
    recentVertices_.clear();
    for (std::size_t i = 0; i < count; ++i)
      processed.push_back(recentVertices_.get(vertices_[indices ? indices[i] : i],
                                              [&](const Vertex& v) { return processVertex(v, vertexLighting); }));
    return processed;
  };
  const bool quads = primitive_ == PrimitiveType::Quads || primitive_ == PrimitiveType::QuadStrip;
  const bool oneProgram = std::all_of(pieces.begin(), pieces.end(), [&](const Piece& p) {
    return p.shininessZero == pieces.front().shininessZero && p.colorVarying == pieces.front().colorVarying;
  });
  if (pieces.size() == 1 || (!quads && oneProgram)) {
    // Cutting a block of triangles, a strip, a fan or a polygon draws the
    // same triangles in the same order: it is drawn whole.
    pieceColorVarying_ = pieces.front().colorVarying;
    std::vector<ClipVertex> processed = processPiece(nullptr, vertices_.size(), pieces.front().shininessZero);
    if (primitive_ == PrimitiveType::QuadStrip) return drawQuadStripPiece(processed);
    if (primitive_ != PrimitiveType::Quads) return drawProcessed(primitive_, processed, false);
    return drawQuadsPiece(std::move(processed));
  }
  if (quads) closeQuadDraw();  // the quad draw held so far is drawn first
  std::vector<std::size_t> piece;  // vertices_ indices, the carried ones first
  std::size_t next = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    for (; next < pieces[p].end; ++next) piece.push_back(next);
    const bool last = p + 1 == pieces.size();
    const std::size_t n = piece.size();
    // A cut strip draws an even number of triangles so that facing is kept.
    const std::size_t drawn = !last && primitive_ == PrimitiveType::TriangleStrip ? n - n % 2 : n;
    std::vector<ClipVertex> processed = processPiece(piece.data(), drawn, pieces[p].shininessZero);
    pieceColorVarying_ = pieces[p].colorVarying;
    if (primitive_ == PrimitiveType::Quads) {
      drawQuadsPiece(std::move(processed));
      if (!last) closeQuadDraw();
    } else if (primitive_ == PrimitiveType::QuadStrip) {
      drawQuadStripPiece(processed);
    } else {
      drawProcessed(primitive_, processed, false);
    }
    if (last) break;
    const std::size_t copied = carriedVertexCount(primitive_, n);
    std::vector<std::size_t> carried;
    if (primitive_ == PrimitiveType::TriangleFan || primitive_ == PrimitiveType::Polygon) {
      if (copied >= 1) carried.push_back(piece.front());
      if (copied >= 2) carried.push_back(piece.back());
    } else {
      carried.assign(piece.end() - static_cast<std::ptrdiff_t>(copied), piece.end());
    }
    piece.swap(carried);
  }
}

std::uint8_t GLContext::shininessVarying() const {
  return static_cast<std::uint8_t>((vboSize_[kVboMaterial + kShininessSlot] != 0 ? 1 : 0) |
                                   (vboSize_[kVboMaterial + 5 + kShininessSlot] != 0 ? 2 : 0));
}

bool GLContext::shininessKeyZero(std::uint8_t varying) const {
  // ffvertex_prog.c make_state_key, check_active_shininess: a shininess is
  // active when the draw's vertex format carries it (a glMaterial since the
  // format was last reset) or its state is not zero; the front's, and the
  // back's too when lighting is two-sided. With none active Mesa's program
  // takes no specular power at all (emit_degenerate_lit). The state is the
  // one at glBegin: inside glBegin/glEnd a glMaterial reaches it only at the
  // next flush.
  const std::array<Material, 2>& state = blockMaterials_.front();
  const bool front = (varying & 1) != 0 || state[0].shininess != 0.0f;
  const bool back = (varying & 2) != 0 || state[1].shininess != 0.0f;
  return !front && !(lighting_.model.twoSide && back);
}

bool GLContext::anyOutsideDrawPlanes(const std::vector<ClipVertex>& processed, std::size_t count) const {
  for (std::size_t i = 0; i < count; ++i)
    if (drawClipMask(processed[i].clip, userPlanesClip_) != 0) return true;
  return false;
}

void GLContext::drawQuadStripPiece(const std::vector<ClipVertex>& processed) {
  // A quad strip is (2, 0, 3) then (0, 1, 3) per quad through the draw
  // module's pipeline (draw_decompose_tmp.h, QUAD(2, 0, 1, 3)), which runs
  // when any vertex lies outside a clip plane; otherwise llvmpipe's setup
  // (lp_setup_vbuf.c) draws the same two triangles in the other order,
  // (0, 1, 3) first, which decides the pixels where a quad overlaps itself.
  // The vbo trims the strip to an even count first: a last odd vertex takes
  // no part in the decision.
  const bool anyOutside = anyOutsideDrawPlanes(processed, processed.size() & ~std::size_t{1});
  drawProcessed(PrimitiveType::QuadStrip, processed, false, !anyOutside);
}

void GLContext::drawQuadsPiece(std::vector<ClipVertex> processed) {
  // Flat shaded with a colour that varies by vertex (lit, or a colour in the
  // vbo's vertex format), a quad keeps its last vertex provoking in both
  // triangles: llvmpipe gets (0, 1, 3) and (1, 2, 3) whether or not the draw
  // clips; with one colour for all it is drawn as smooth quads are (measured
  // against GL_TRIANGLES in each order: flat_quad_depth_order.gls).
  if (flatShading_ && (lightingEnabled_ || pieceColorVarying_)) {
    closeQuadDraw();
    return drawProcessed(PrimitiveType::Quads, processed, true);
  }
  // llvmpipe draws quads as MPR does, (0, 1, 2) and (0, 2, 3), except when
  // Mesa's draw module runs its pipeline, which it does when any vertex of
  // the draw lies outside a clip plane: then draw_decompose_tmp.h splits each
  // quad along the other diagonal, (0, 1, 3) and (1, 2, 3), and that split
  // decides coverage, colour and depth. A draw is every GL_QUADS block since
  // the last state change (Mesa's vbo merges them while the earlier count is
  // a multiple of 4; vbo_merge_draws), so the split of a block can depend on
  // a later one: blocks wait in quadDraw_ until the draw is known to clip or
  // is closed.
  // As for strips, the draw is trimmed to whole quads first (draw_pt.c
  // draw_pt_trim_count): vertices after the last whole quad take no part.
  const bool anyOutside = anyOutsideDrawPlanes(processed, processed.size() & ~std::size_t{3});
  if (!quadDraw_.open || quadDraw_.vertexCount % 4 != 0 || quadDraw_.colorVarying != pieceColorVarying_) {
    closeQuadDraw();
    quadDraw_ = OpenQuadDraw{true, false, 0, {}, pieceColorVarying_};
  }
  quadDraw_.vertexCount += processed.size();
  if (quadDraw_.clipped) return drawProcessed(PrimitiveType::Quads, processed, true);
  if (anyOutside) {
    quadDraw_.clipped = true;
    std::vector<ClipVertex> waiting;
    waiting.swap(quadDraw_.waiting);
    if (!waiting.empty()) drawProcessed(PrimitiveType::Quads, waiting, true);
    return drawProcessed(PrimitiveType::Quads, processed, true);
  }
  quadDraw_.waiting.insert(quadDraw_.waiting.end(), processed.begin(), processed.end());
}

void GLContext::drawProcessed(PrimitiveType type, const std::vector<ClipVertex>& processed, bool quadsOtherDiagonal,
                              bool pairsSwapped) {
  std::vector<AssembledTriangle> tris = assembleTriangles(type, static_cast<std::uint32_t>(processed.size()));
  if (tris.empty()) return;
  if (pairsSwapped)
    for (std::size_t k = 0; k + 1 < tris.size(); k += 2) std::swap(tris[k], tris[k + 1]);
  if (quadsOtherDiagonal)
    for (std::size_t k = 0; k < tris.size(); k += 2) {
      const std::uint32_t q = tris[k].v[0];  // MPR's quad triangles both start at the quad's first vertex
      tris[k] = {{q, q + 1, q + 3}, q + 3};
      tris[k + 1] = {{q + 1, q + 2, q + 3}, q + 3};
    }
  const std::vector<ClipPlane>& userPlanes = userPlanesClip_;
  const WindowTransform window{vpScaleX_, vpTransX_, vpScaleY_, vpTransY_,
                               static_cast<float>((depthFar_ - depthNear_) / 2.0),
                               static_cast<float>((depthNear_ + depthFar_) / 2.0), fb_.height()};

  // The state cannot change within a draw: the per-fragment function is
  // chosen once, and one set of llvmpipe planes is reused (no allocation per
  // triangle once it has grown).
  fragmentPipeline_ = chooseFragmentPipeline(frag_);
  // With threads and no observer the triangles are set up here and queued
  // together at the end, for the row threads to draw (drawDeferred).
  deferring_ = rowQueue != nullptr && !fragmentObserver;
  LlvmpipeDepth depth{window, &userPlanes, {}};
  const bool cullsBeforeSetUp = cullEnabled_ && !windowMap_;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    if (deferring_) {
      // A long draw is queued a piece at a time, so the row threads start
      // on its first triangles while the rest are being set up (a draw of
      // the bathroom trace has up to 4 000).
      if (deferred_.size() >= kTrianglesPerQueuedDraw) drawDeferred();
      // drawDeferred hands these vectors to the queued piece, so each piece
      // starts them empty: sized once for it (a triangle is one set-up
      // unless MPR's clipper cuts it), not grown by doubling, which copied
      // every set-up so far (half of the set-up's time on the bathroom trace).
      if (deferred_.empty()) {
        const std::size_t piece = std::min(tris.size() - k, kTrianglesPerQueuedDraw);
        deferred_.reserve(piece);
        deferredClipped_.reserve(piece);
      }
    }
    const AssembledTriangle& t = tris[k];
    std::array<ClipVertex, 3> tri = {processed[t.v[0]], processed[t.v[1]], processed[t.v[2]]};
    if (flatShading_)
      for (ClipVertex& cv : tri)
        for (int i = 0; i < 8; ++i) cv.attr[i] = processed[t.provoking].attr[i];
    // A culled triangle llvmpipe does not clip is dropped before its
    // set-up, counted as drawTriangle counts it (with culling on, half of a
    // closed mesh's triangles face away: 214 000 of the bathroom trace's
    // 480 000 unclipped ones were set up only to be culled).
    if (cullsBeforeSetUp && culledBeforeSetUp(tri, window)) {
      ++counters_.triangles;
      ++counters_.trianglesDrawn;
      continue;
    }
    depth.triangles.clear();
    // The end-of-pipeline stage interpolates depth itself (only the window
    // transform is used): no llvmpipe planes to set up.
    if (!windowMap_) depth.add(tri[0], tri[1], tri[2]);
    drawTriangle(tri, depth);
  }
  drawDeferred();
  deferring_ = false;
}

MPR_CPU_CLONES bool GLContext::culledBeforeSetUp(const std::array<ClipVertex, 3>& tri, const WindowTransform& window) const {
  // rasterizeClippedTriangle's facing test first, before anything it sets
  // up (a triangle it draws costs no more than this): a vertex whose
  // position is not finite, no area, or culled.
  std::array<SnappedVertex, 3> snapped;
  bool finite = true;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!snapLikeLlvmpipeRaster(tri[i], window, fb_.height(), snapped[i])) {
      finite = false;
    } else if (!areaCannotOverflow(snapped[i])) {
      // A vertex near the eye plane (w a hair above 0) snaps far enough out
      // that the area's products would overflow: the full path decides
      // (such a triangle is clipped, so this one would not drop it anyway).
      return false;
    }
  }
  if (finite) {
    const std::int64_t area = signedArea2(snapped[0], snapped[1], snapped[2]);
    if (area != 0 && facingColorOffset(area > 0) >= 0) return false;
  }
  // Then whether drawTriangle takes it there: finite, not clipped by draw
  // (LlvmpipeDepth::add's masks), inside the user planes, w > 0.
  for (const ClipVertex& v : tri) {
    if (!finite4(v.clip) || !(v.clip.w > 0.0f) || drawClipMask(v.clip, userPlanesClip_) != 0) return false;
    for (float a : v.attr)
      if (!std::isfinite(a)) return false;
  }
  return insideAllPlanes(tri, std::span<const ClipPlane>(clipPlanesClip_).subspan(6));
}

void GLContext::drawTriangle(const std::array<ClipVertex, 3>& tri, const LlvmpipeDepth& depth) {
  ++counters_.triangles;
  // A vertex that is not finite drops its primitive and touches nothing else.
  for (const ClipVertex& v : tri) {
    if (!finite4(v.clip)) return;
    for (float a : v.attr)
      if (!std::isfinite(a)) return;
  }
  // Where Mesa's draw module clips the triangle, llvmpipe rasterises the fan
  // draw makes of it, so that fan decides the coverage (and its planes the
  // depth); MPR's own clipper would cover slightly other pixels along the
  // edges clipping makes (issue 17 class 4, large_coordinates_clip.gls).
  if (!windowMap_ && depth.clipped) return rasterizeLlvmpipeFan(depth);
  // Inside every plane, clipPolygon would return the triangle as it is.
  // Without a window map, depth.add found draw's clip masks all clear (a
  // clipped triangle went to its fan above), so the six view-volume planes
  // hold already: for finite vertices each of their distances is the very
  // sum drawClipMask compares (x + w, w - x, ...), and only the user planes,
  // which drawClipMask evaluates fused, are asked again.
  const bool viewVolumeHolds = !windowMap_;
  if (insideAllPlanes(tri, std::span<const ClipPlane>(clipPlanesClip_).subspan(viewVolumeHolds ? 6 : 0))) {
    for (const ClipVertex& v : tri)
      if (!(v.clip.w > 0.0f)) return;
    ++counters_.trianglesDrawn;
    return rasterizeClippedTriangle(tri[0], tri[1], tri[2], depth);
  }
  std::vector<ClipVertex> poly(tri.begin(), tri.end());
  poly = clipPolygon(std::move(poly), clipPlanesClip_);
  if (poly.size() < 3) return;
  for (const ClipVertex& v : poly)
    if (!(v.clip.w > 0.0f)) return;  // only the point (0,0,0,0) survives clipping with w <= 0
  ++counters_.trianglesDrawn;
  for (size_t i = 1; i + 1 < poly.size(); ++i) rasterizeClippedTriangle(poly[0], poly[i], poly[i + 1], depth);
}

inline void GLContext::submitFragment(Fragment& f, const DrawState& state, FragmentTally& tally) {
  ++tally.tested;
  if (state.observed) {
    const int x = f.x, y = f.y;
    FragmentEvent ev{x, y, fb_.stencil(x, y), 0, fb_.depth(x, y), f.depth, FragmentFate::Written, {}};
    ev.fate = state.pipeline.fragment(state.frag, fb_, f);
    ev.stencilAfter = fb_.stencil(x, y);
    ev.colorAfter = fb_.color(x, y);
    if (ev.fate == FragmentFate::Written) ++tally.written;
    fragmentObserver(ev);
    return;
  }
  if (state.pipeline.fragment(state.frag, fb_, f) == FragmentFate::Written) ++tally.written;
}

inline bool GLContext::stencilRejectsSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally) {
  if (!state.pipeline.stencilRejectsAll || state.observed) return false;  // observed: each fragment seen whole
  if (!state.pipeline.stencilRejectsAll(state.frag, fb_, span.x, span.y, span.count)) return false;
  tally.tested += static_cast<std::uint64_t>(span.count);
  return true;
}

inline void GLContext::submitSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally) {
  if (state.observed) {  // fragment by fragment, in the span's order, each one seen
    for (int i = 0; i < span.count; ++i) {
      Fragment f{span.x + i, span.y, span.depth[i], span.color[i], span.alpha[i]};
      submitFragment(f, state, tally);
    }
    return;
  }
  tally.tested += static_cast<std::uint64_t>(span.count);
  tally.written += state.pipeline.span(state.frag, fb_, span);
}

void GLContext::setThreads(int threads) {
  drain();
  rowQueue.reset();  // its threads stopped before rowTallies changes
  rowTallies.assign(threads > 1 ? static_cast<std::size_t>(threads) : 0, RowTally{});
  if (threads > 1) rowQueue = std::make_unique<RowQueue>(threads);
}

// A template, not a std::function: the per-triangle call would otherwise
// allocate for the rows' closure.
template <typename Rows>
void GLContext::drawNow(const Rows& rows) {
  if (rowQueue && !fragmentObserver) {
    const int n = rowQueue->threads();
    rowQueue->push([&, n](int k) { rows(rowTallies[static_cast<std::size_t>(k)].tally, n, k); });
    drain();  // `rows` refers to this call's set-up
    return;
  }
  drain();  // what is queued goes first
  FragmentTally tally;
  rows(tally, 1, 0);
  counters_.fragmentsTested += tally.tested;
  counters_.fragmentsWritten += tally.written;
}

int GLContext::facingColorOffset(bool ccw) const {
  const bool front = (frontFace_ == GL_CCW) == ccw;
  if (cullEnabled_ && (cullMode_ == GL_FRONT_AND_BACK || (cullMode_ == GL_FRONT) == front)) return -1;
  return (front || !(lightingEnabled_ && lighting_.model.twoSide)) ? 0 : 4;
}

MPR_CPU_CLONES void GLContext::rasterizeClippedTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                         const LlvmpipeDepth& depth) {
  const ClipVertex* v[3] = {&a, &b, &c};
  std::array<SnappedVertex, 3> snapped;
  double invW[3], xWin[3], yWin[3], mapZ[3] = {0.0, 0.0, 0.0}, mapInvQ[3] = {1.0, 1.0, 1.0};
  for (int i = 0; i < 3; ++i) {
    const float iw = 1.0f / v[i]->clip.w;
    float xn = v[i]->clip.x * iw, yn = v[i]->clip.y * iw;
    if (windowMap_) {
      // [u v q] = [x y 1] M on normalised device coordinates; the vertex
      // goes to (u/q, v/q) and keeps its depth. Attributes and depth are then
      // interpolated as in the unmapped image: a projective map divides the
      // screen-space weights by q (so 1/w becomes 1/(w q), and depth, linear
      // on the unmapped screen, is weighted by 1/q).
      const glm::mat3& m = *windowMap_;
      const float q = m[2][0] * xn + m[2][1] * yn + m[2][2];
      if (!(q > 0.0f)) return;  // clipped to q >= |u|: only a point can reach q = 0
      const float u = m[0][0] * xn + m[0][1] * yn + m[0][2], w = m[1][0] * xn + m[1][1] * yn + m[1][2];
      mapZ[i] = static_cast<double>(v[i]->clip.z * iw * depth.window.scaleZ + depth.window.transZ);
      mapInvQ[i] = 1.0 / static_cast<double>(q);
      xn = u / q;
      yn = w / q;
    }
    const float xw = xn * vpScaleX_ + vpTransX_;
    const float yw = yn * vpScaleY_ + vpTransY_;
    // A denormal w (1/w = inf) puts the vertex at an infinite window
    // position: the primitive is dropped like one with a non-finite vertex.
    if (!std::isfinite(xw) || !std::isfinite(yw)) return;
    invW[i] = static_cast<double>(iw) * mapInvQ[i];
    xWin[i] = xw;
    yWin[i] = yw;
    if (windowMap_) {
      snapped[i] = snapVertex(xw, yw);
    } else {
      // Coverage from the window position llvmpipe snaps (fused, on OSMesa's
      // flipped rows): MPR's unfused y-up position can differ by an ulp, and
      // on a sliver that moves a pixel centre across an edge (lighting seed
      // 1113).
      if (!snapLikeLlvmpipeRaster(*v[i], depth.window, fb_.height(), snapped[i])) return;
    }
  }
  const std::int64_t area = signedArea2(snapped[0], snapped[1], snapped[2]);
  if (area == 0) return;
  const int colorOffset = facingColorOffset(area > 0);
  if (colorOffset < 0) return;

  const PixelRect region = drawRegion();
  if (region.empty()) return;
  const PixelBounds bounds{region.x0, region.y0, region.x1, region.y1};
  // Where llvmpipe's clipping dropped what MPR's kept, MPR's own triangle
  // stands in (it is then at most a few pixels of an edge).
  std::optional<LlvmpipeDepth> fallback;  // (its vectors made only when it is)
  if (depth.triangles.empty()) {
    fallback.emplace(LlvmpipeDepth{depth.window, depth.userPlanes, {}});
    if (!windowMap_) fallback->add(a, b, c);
  }
  const LlvmpipeDepth& depthPlanes = fallback ? *fallback : depth;

  // The triangle's rows within the region: none, and nothing is set up.
  const std::int64_t top = std::max({snapped[0].y, snapped[1].y, snapped[2].y});
  const std::int64_t bottom = std::min({snapped[0].y, snapped[1].y, snapped[2].y});
  const std::int64_t rowLo = std::max<std::int64_t>(bounds.y0, ceilDivSubpixel(bottom));
  const std::int64_t rowHi = std::min<std::int64_t>(bounds.y1 - 1, floorDivSubpixel(top));
  if (rowLo > rowHi) return;
  // Several planes are looked up in a set-up that lives for this call only:
  // such a triangle is drawn now, after what the draw has deferred. Any
  // other is set up where the draw keeps it (no copy of the set-up).
  const bool severalPlanes = frag_.depth.enabled && !windowMap_ && depthPlanes.triangles.size() > 1;
  const bool deferred = deferring_ && !severalPlanes;
  ClippedTriangleRows drawnNow;
  ClippedTriangleRows& job = deferred ? deferredClipped_.emplace_back() : drawnNow;
  job.snapped = snapped;
  job.bounds = bounds;

  // Coverage is decided on the snapped vertices; colours are interpolated on
  // the unsnapped window positions, as llvmpipe sets up its planes (depth
  // follows llvmpipe's own arithmetic, see LlvmpipeDepth). All of it is set
  // up here once; shadeSpan does the per-pixel part a row span at a time.
  TriangleShading& t = job.shading;
  t.depthMax = static_cast<float>(fb_.profile().depthMax());
  t.fbHeight = fb_.height();
  if (frag_.depth.enabled) {
    if (windowMap_) {
      t.depth = TriangleShading::Depth::WindowMap;
      for (int i = 0; i < 3; ++i) {
        t.mapZ[i] = mapZ[i];
        t.mapInvQ[i] = mapInvQ[i];
      }
    } else if (depthPlanes.triangles.size() == 1) {
      t.depth = TriangleShading::Depth::OnePlane;
      t.a0 = depthPlanes.triangles[0].a0;
      t.dzdx = depthPlanes.triangles[0].dzdx;
      t.dzdy = depthPlanes.triangles[0].dzdy;
    } else if (!depthPlanes.triangles.empty()) {
      t.depth = TriangleShading::Depth::Planes;
      t.planes = &depthPlanes;
    }
  }
  t.color = needsColor(frag_);
  t.uniformColor = uniformColor();
  if (fog_.enabled) t.fog = &fog_;
  // llvmpipe draws the triangle as one: its colours are that triangle's
  // planes (also where MPR's own clipper made pieces of it).
  t.llvmpipeColor = t.color && !windowMap_ && depthPlanes.triangles.size() == 1;
  if (t.llvmpipeColor)
    setUpChannelPlanes(depthPlanes.triangles[0], colorOffset, t.uniformColor, t.fog != nullptr, t.channels);
  // The exact weights and the vertices' channels: read by shadeSpan only
  // for MPR's own colours or the window map's depth (most triangles, those
  // of llvmpipe's colour planes or of no colour, skip them).
  if ((t.color && !t.llvmpipeColor) || t.depth == TriangleShading::Depth::WindowMap) {
    t.ex1 = xWin[1] - xWin[0];
    t.ey1 = yWin[1] - yWin[0];
    t.ex2 = xWin[2] - xWin[0];
    t.ey2 = yWin[2] - yWin[0];
    t.xWin0 = xWin[0];
    t.yWin0 = yWin[0];
    t.exactArea = t.ex1 * t.ey2 - t.ex2 * t.ey1;
    t.useSnapped = !(std::fabs(t.exactArea) > 0.0);  // degenerate before snapping
    t.snappedArea = static_cast<double>(area > 0 ? area : -area);  // the weights' sum
    for (int i = 0; i < 3; ++i) t.invW[i] = invW[i];
    vertexChannels(a, b, c, colorOffset, t.attr, t.constant);
    decideFlatColor(t);
  }

  if (deferred) {
    deferred_.push_back({static_cast<std::uint32_t>(deferredClipped_.size() - 1), false});
    return;
  }
  if (deferring_) drawDeferred();
  const DrawState state = currentDrawState();
  drawNow([&](FragmentTally& tally, int stride, int phase) {
    FragmentSpan fragments;  // per share: shares run at once
    drawRows(job, state, tally, stride, phase, fragments);
  });
}

void GLContext::drawRows(const ClippedTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride,
                         int phase, FragmentSpan& fragments) {
  rasterizeTriangleSpans(
      job.snapped, job.bounds,
      [&](const CoveredSpan& covered) {
        // The row in pieces of at most kCapacity, in x order.
        for (int done = 0; done < covered.count; done += FragmentSpan::kCapacity) {
          fragments.x = covered.x + done;
          fragments.y = covered.y;
          fragments.count = std::min(FragmentSpan::kCapacity, covered.count - done);
          if (stencilRejectsSpan(fragments, state, tally)) continue;
          std::array<std::int64_t, 3> w;
          for (int i = 0; i < 3; ++i) w[i] = covered.w[i] + done * covered.stepX[i];
          shadeSpan(job.shading, w, covered.stepX, fragments);
          submitSpan(fragments, state, tally);
        }
      },
      stride, phase);
}

void GLContext::rasterizeLlvmpipeFan(const LlvmpipeDepth& depth) {
  if (depth.triangles.empty()) return;  // llvmpipe draws nothing of it
  ++counters_.trianglesDrawn;
  const PixelRect region = drawRegion();
  if (region.empty()) return;
  const int fbHeight = fb_.height();
  FanShading shading;
  shading.depthMax = static_cast<float>(fb_.profile().depthMax());
  shading.fbHeight = fbHeight;
  shading.depth = frag_.depth.enabled;
  shading.color = needsColor(frag_);
  if (fog_.enabled) shading.fog = &fog_;
  // The region in llvmpipe's y-down rows.
  const int rowLo = fbHeight - region.y1, rowHi = fbHeight - 1 - region.y0;
  for (const LlvmpipeDepth::Triangle& t : depth.triangles) {
    const int colorOffset = facingColorOffset(t.ccwUp);
    if (colorOffset < 0) continue;
    FanTriangleRows job{shading, t, 0, 0, 0, 0};
    FanShading& fan = job.shading;
    fan.a0 = t.a0;
    fan.dzdx = t.dzdx;
    fan.dzdy = t.dzdy;
    if (fan.color) setUpChannelPlanes(t, colorOffset, uniformColor(), fan.fog != nullptr, fan.planes);
    // Bounds of the pixels whose centres the fixed-point edges can cover
    // (positions are (v - 0.5) * 256: pixel x's centre is at x * 256).
    const std::int64_t minX = std::min({t.fixedX[0], t.fixedX[1], t.fixedX[2]}),
                       maxX = std::max({t.fixedX[0], t.fixedX[1], t.fixedX[2]});
    const std::int64_t minY = std::min({t.fixedY[0], t.fixedY[1], t.fixedY[2]}),
                       maxY = std::max({t.fixedY[0], t.fixedY[1], t.fixedY[2]});
    job.x0 = std::max<std::int64_t>(region.x0, floorDivide(minX, 256));
    job.x1 = std::min<std::int64_t>(region.x1 - 1, floorDivide(maxX, 256) + 1);
    job.y0 = std::max<std::int64_t>(rowLo, floorDivide(minY, 256));
    job.y1 = std::min<std::int64_t>(rowHi, floorDivide(maxY, 256) + 1);
    if (t.wrapsSteps) {
      // lp_setup.c draw_regions: the framebuffer, within the scissor box
      // (not the viewport). Blocks are filled whole past the triangle's own
      // box, and so past the region where the box kept llvmpipe from adding
      // a scissor plane on that side: any pixel of the framebuffer.
      PixelRect r = fb_.bounds();
      if (scissorEnabled_) r = r.intersect(scissorBox_);
      if (r.empty()) continue;
      job.llvmpipeRegion = {r.x0, fbHeight - r.y1, r.x1 - 1, fbHeight - 1 - r.y0};
      job.x0 = 0;
      job.x1 = fb_.width() - 1;
      job.y0 = 0;
      job.y1 = fbHeight - 1;
    }
    if (job.x0 > job.x1 || job.y0 > job.y1) continue;
    if (deferring_) {
      defer(job);
      continue;
    }
    const DrawState state = currentDrawState();
    drawNow([&](FragmentTally& tally, int stride, int phase) {
      FragmentSpan fragments;  // per share: shares run at once
      drawRows(job, state, tally, stride, phase, fragments);
    });
  }
}

void GLContext::drawRows(const FanTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride,
                         int phase, FragmentSpan& fragments) {
  const LlvmpipeDepth::Triangle& t = job.triangle;
  const int fbHeight = fb_.height();
  // The share's rows are GL rows y = fbHeight - 1 - yDown with y mod stride
  // == phase (the same rows a clipped triangle's share holds).
  const std::int64_t wanted = ((fbHeight - 1 - phase) % stride + stride) % stride;  // yDown mod stride
  const std::int64_t first = job.y0 + ((wanted - job.y0 % stride) % stride + stride) % stride;
  auto drawSpan = [&](int y, std::int64_t spanLo, std::int64_t spanHi) {
    for (std::int64_t from = spanLo; from <= spanHi; from += FragmentSpan::kCapacity) {
      fragments.x = static_cast<int>(from);
      fragments.y = y;
      fragments.count = static_cast<int>(std::min<std::int64_t>(FragmentSpan::kCapacity, spanHi - from + 1));
      if (stencilRejectsSpan(fragments, state, tally)) continue;
      shadeFanSpan(job.shading, fragments);
      submitSpan(fragments, state, tally);
    }
  };
  if (t.wrapsSteps) {
    // Steps that wrap: the pixels llvmpipe's tiles and blocks reach, each
    // row's runs of them (rare: an edge through the clip-space origin).
    const std::array<int, 4>& r = job.llvmpipeRegion;
    const LlvmpipeTileRaster raster(t, r[0], r[1], r[2], r[3]);
    if (raster.emulated()) {
      for (std::int64_t yDown = first; yDown <= job.y1; yDown += stride) {
        const int y = fbHeight - 1 - static_cast<int>(yDown);
        for (std::int64_t x = job.x0; x <= job.x1; ++x) {
          if (!raster.covers(static_cast<int>(x), static_cast<int>(yDown))) continue;
          std::int64_t last = x;
          while (last < job.x1 && raster.covers(static_cast<int>(last + 1), static_cast<int>(yDown))) ++last;
          drawSpan(y, x, last);
          x = last;
        }
      }
      return;
    }
  }
  // Each row's span: the pixels a test of covers()' half-planes would pass.
  LlvmpipeRowSpans rows(t, first, stride, job.x0, job.x1);
  for (std::int64_t yDown = first; yDown <= job.y1; yDown += stride) {
    std::int64_t spanLo, spanHi;
    rows.next(spanLo, spanHi);
    drawSpan(fbHeight - 1 - static_cast<int>(yDown), spanLo, spanHi);
  }
}

// A draw's triangles are set up one after the other and kept (deferring_),
// then queued together (drawDeferred): row thread k draws the rows y with
// y mod n == k of every triangle, in the triangles' order, so each pixel
// still sees its fragments in submission order, whatever n is, and small
// triangles are shared out too (llvmpipe bins its triangles into tiles for
// the same end).
void GLContext::defer(const FanTriangleRows& job) {
  deferred_.push_back({static_cast<std::uint32_t>(deferredFan_.size()), true});
  deferredFan_.push_back(job);
}

void GLContext::drawDeferred() {
  if (deferred_.empty()) return;
  // The queued draw: its triangles and the state they are drawn with,
  // copied, since the calls after it go on changing the context's.
  struct Draw {
    FragmentState frag;
    FragmentPipeline pipeline;
    FogState fog;
    std::vector<DeferredTriangle> order;
    std::vector<ClippedTriangleRows> clipped;
    std::vector<FanTriangleRows> fan;
  };
  // Its set-ups' storage goes back to spentClipped_ when the draw is done,
  // and the next draw sets up into storage from there.
  std::shared_ptr<Draw> draw(new Draw{frag_, fragmentPipeline_, fog_, std::move(deferred_), {}, {}},
                             [pool = spentClipped_](Draw* d) {
                               pool->give(std::move(d->clipped));
                               delete d;
                             });
  draw->clipped = std::move(deferredClipped_);
  deferredClipped_ = spentClipped_->take();
  draw->fan = std::move(deferredFan_);
  // The shading read the context's fog; the copy is the draw's now.
  for (ClippedTriangleRows& j : draw->clipped)
    if (j.shading.fog) j.shading.fog = &draw->fog;
  for (FanTriangleRows& j : draw->fan)
    if (j.shading.fog) j.shading.fog = &draw->fog;
  deferred_.clear();
  deferredFan_.clear();
  const int n = rowQueue->threads();
  rowQueue->push([this, draw, n](int k) {
    const DrawState state{draw->frag, draw->pipeline, false};
    FragmentTally& tally = rowTallies[static_cast<std::size_t>(k)].tally;
    // One span for the thread's share of the whole draw: its 780 bytes were
    // cleared per triangle (a twentieth of the row threads' time).
    FragmentSpan fragments;
    for (const DeferredTriangle& d : draw->order) {
      if (d.fan) drawRows(draw->fan[d.index], state, tally, n, k, fragments);
      else drawRows(draw->clipped[d.index], state, tally, n, k, fragments);
    }
  });
}

}  // namespace mpr
