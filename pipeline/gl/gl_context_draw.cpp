// GLContext: glBegin/glVertex/glEnd, Mesa's vbo (its vertex format, the
// pieces it cuts a block into, the GL_QUADS draws it merges, its flushes),
// vertex processing, and each draw handed on to the draw stage with its
// frozen DrawSnapshot.
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipeline/gl/gl_context.hpp"
#include "pipeline/draw/mesa_matrix_inverse.hpp"
#include "util/transforms.hpp"

namespace mpr {
namespace {

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
  // Drawn with its own vertex format.
  if (!quadDraw_.clipped && !waiting.empty())
    draw_.draw(drawSnapshot(quadDraw_.colorVarying), PrimitiveType::Quads, waiting);
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

void GLContext::end() {
  if (!inBegin_) return setError(GL_INVALID_OPERATION);
  inBegin_ = false;
  deriveBlockState();
  const std::vector<VboPiece> pieces = vboPieces();
  LightingState lighting = blockLighting();
  const bool quads = primitive_ == PrimitiveType::Quads || primitive_ == PrimitiveType::QuadStrip;
  const bool oneProgram = std::all_of(pieces.begin(), pieces.end(), [&](const VboPiece& p) {
    return p.shininessZero == pieces.front().shininessZero && p.colorVarying == pieces.front().colorVarying;
  });
  if (pieces.size() == 1 || (!quads && oneProgram)) {
    // Cutting a block of triangles, a strip, a fan or a polygon draws the
    // same triangles in the same order: it is drawn whole.
    drawPiece(processPiece(nullptr, vertices_.size(), pieces.front().shininessZero, lighting),
              pieces.front().colorVarying, true);
    return;
  }
  drawInPieces(pieces, lighting);
}

void GLContext::deriveBlockState() {
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
  // The block's clip planes, in clip coordinates, straight into the snapshot
  // its draws are handed on with (drawSnapshot leaves them as they are).
  std::vector<ClipPlane>& planes = drawSnapshot_.clipPlanes;
  planes = viewVolumePlanes();
  // _mesa_update_clip_plane: the eye plane by the projection's inverse as
  // Mesa keeps it (the clip-space planes st_atom_clip.c hands the draw module).
  const Mat4& projInverse = projection_.mesaTop().inverse;  // analysed at glBegin
  for (int i = 0; i < 6; ++i)
    if (clipPlaneEnabled_[i]) planes.push_back(mesaTransformRowVector(clipPlanesEye_[i], projInverse));
  drawSnapshot_.userPlanes.assign(planes.begin() + DrawSnapshot::kViewVolumePlanes, planes.end());
  if (windowMap_) {
    // The end-of-pipeline map: what lands in the viewport is |u| <= q and
    // |v| <= q (so q >= 0), which is linear in clip coordinates (u w is
    // M[0] . (x, y, w)): the view volume's four sides are replaced by these,
    // so the clipper keeps exactly what the map puts on the screen.
    const glm::mat3& m = *windowMap_;
    const Vec4 u(m[0][0], m[0][1], 0.0f, m[0][2]), v(m[1][0], m[1][1], 0.0f, m[1][2]),
        q(m[2][0], m[2][1], 0.0f, m[2][2]);
    planes[2] = q + u;
    planes[3] = q - u;
    planes[4] = q + v;
    planes[5] = q - v;
  }
}

std::vector<GLContext::VboPiece> GLContext::vboPieces() {
  // The vbo cut the block where an attribute joined its vertex format
  // (vboAttribute): the vertices stored so far are drawn, and the vertices
  // of the unfinished primitive begin the next piece (vbo_copy_vertices).
  // Each piece is a draw of its own with the fixed-function program its
  // vertex format selects, and a vertex carried over is lit again by it.
  std::vector<VboPiece> pieces;
  for (const BlockWrap& w : blockWraps_)
    pieces.push_back({w.vertex, shininessKeyZero(w.shininessVarying), w.colorVarying});
  pieces.push_back({vertices_.size(), shininessKeyZero(shininessVarying()), vboSize_[kVboColor] != 0});
  blockWraps_.clear();
  return pieces;
}

LightingState GLContext::blockLighting() const {
  // The lighting state every vertex of a draw shares, copied once (it is a
  // kilobyte); each vertex sets its own materials in it.
  LightingState lighting;
  if (lightingEnabled_) {
    lighting = lighting_;
    // On the flags analysed at glBegin (lighting_object_space.gls).
    if (mesaLightsInObjectSpace(lighting_, modelview_.mesaTop().flags))
      toObjectSpace(lighting, modelview_.top(), modelview_.mesaTop().inverse);
  }
  return lighting;
}

std::vector<ClipVertex> GLContext::processPiece(const std::size_t* indices, std::size_t count, bool shininessZero,
                                                LightingState& lighting) {
  lighting.shininessKeyZero = shininessZero;
  lighting.mesaShininess0Attenuated = shininessZero && (departures_ & kShininess0Attenuated);
  const VertexSnapshot snapshot = vertexSnapshot();
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
                                            [&](const Vertex& v) { return processVertex(snapshot, v, lighting); }));
  return processed;
}

VertexSnapshot GLContext::vertexSnapshot() const {
  VertexSnapshot s;
  s.mvp = mvp_;
  s.modelview = modelview_.top();
  s.normalMatrix = normalMatrix_;
  s.lighting = lightingEnabled_;
  s.normalize = normalize_;
  s.twoSide = lighting_.model.twoSide;
  // The vertex's own colour feeds the tracked material parameter where the
  // colour varies in the draw (a glColor since the vbo's format was last
  // reset); otherwise Mesa's fixed-function program reads the material
  // state, which enabling GL_COLOR_MATERIAL set from the colour and a held
  // glMaterial may have set back (copyToCurrent).
  s.colorTracksMaterial = colorMaterialEnabled_ && vboSize_[kVboColor] != 0;
  s.colorMaterialFaces = colorMaterialFace_ == GL_FRONT  ? MaterialFaces::Front
                         : colorMaterialFace_ == GL_BACK ? MaterialFaces::Back
                                                         : MaterialFaces::FrontAndBack;
  switch (colorMaterialMode_) {
    case GL_EMISSION: s.colorMaterialParam = ColorMaterialParam::Emission; break;
    case GL_AMBIENT: s.colorMaterialParam = ColorMaterialParam::Ambient; break;
    case GL_DIFFUSE: s.colorMaterialParam = ColorMaterialParam::Diffuse; break;
    case GL_SPECULAR: s.colorMaterialParam = ColorMaterialParam::Specular; break;
    default: s.colorMaterialParam = ColorMaterialParam::AmbientAndDiffuse; break;
  }
  s.lightingUndividedEye = (departures_ & kLightingUndividedEye) != 0;
  s.fog = fog_;
  s.materials = blockMaterials_;
  return s;
}

void GLContext::drawPiece(std::vector<ClipVertex> processed, bool colorVarying, bool last) {
  switch (primitive_) {
    case PrimitiveType::Quads:
      drawQuadsPiece(std::move(processed), colorVarying);
      if (!last) closeQuadDraw();
      return;
    default: draw_.draw(drawSnapshot(colorVarying), primitive_, processed); return;
  }
}

void GLContext::drawInPieces(const std::vector<VboPiece>& pieces, LightingState& lighting) {
  const bool quads = primitive_ == PrimitiveType::Quads || primitive_ == PrimitiveType::QuadStrip;
  if (quads) closeQuadDraw();  // the quad draw held so far is drawn first
  std::vector<std::size_t> piece;  // vertices_ indices, the carried ones first
  std::size_t next = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    for (; next < pieces[p].end; ++next) piece.push_back(next);
    const bool last = p + 1 == pieces.size();
    const std::size_t n = piece.size();
    // A cut strip draws an even number of triangles so that facing is kept.
    const std::size_t drawn = !last && primitive_ == PrimitiveType::TriangleStrip ? n - n % 2 : n;
    drawPiece(processPiece(piece.data(), drawn, pieces[p].shininessZero, lighting), pieces[p].colorVarying, last);
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

void GLContext::drawQuadsPiece(std::vector<ClipVertex> processed, bool colorVarying) {
  // Flat shaded with a colour that varies by vertex (lit, or a colour in the
  // vbo's vertex format), a quad keeps its last vertex provoking in both
  // triangles: llvmpipe gets (0, 1, 3) and (1, 2, 3) whether or not the draw
  // clips; with one colour for all it is drawn as smooth quads are (measured
  // against GL_TRIANGLES in each order: flat_quad_depth_order.gls).
  if (flatShading_ && (lightingEnabled_ || colorVarying)) {
    closeQuadDraw();
    return draw_.draw(drawSnapshot(colorVarying), PrimitiveType::Quads, processed, true);
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
  if (!quadDraw_.open || quadDraw_.vertexCount % 4 != 0 || quadDraw_.colorVarying != colorVarying) {
    closeQuadDraw();
    quadDraw_ = OpenQuadDraw{true, false, 0, {}, colorVarying};
  }
  const DrawSnapshot& snapshot = drawSnapshot(colorVarying);
  const bool anyOutside = DrawStage::runsDrawPipeline(snapshot, processed, processed.size() & ~std::size_t{3});
  quadDraw_.vertexCount += processed.size();
  if (quadDraw_.clipped) return draw_.draw(snapshot, PrimitiveType::Quads, processed, true);
  if (anyOutside) {
    quadDraw_.clipped = true;
    std::vector<ClipVertex> waiting;
    waiting.swap(quadDraw_.waiting);
    if (!waiting.empty()) draw_.draw(snapshot, PrimitiveType::Quads, waiting, true);
    return draw_.draw(snapshot, PrimitiveType::Quads, processed, true);
  }
  quadDraw_.waiting.insert(quadDraw_.waiting.end(), processed.begin(), processed.end());
}

const DrawSnapshot& GLContext::drawSnapshot(bool colorVarying) {
  DrawSnapshot& s = drawSnapshot_;
  s.frag = frag_;
  // The state cannot change within a draw: the per-fragment function is
  // chosen once for it.
  s.pipeline = chooseFragmentPipeline(frag_);
  s.observer = fragmentObserver ? &fragmentObserver : nullptr;
  s.cullEnabled = cullEnabled_;
  s.cullFace = cullMode_ == GL_FRONT ? CullFace::Front : cullMode_ == GL_BACK ? CullFace::Back : CullFace::FrontAndBack;
  s.frontFaceCcw = frontFace_ == GL_CCW;
  s.twoSidedColors = lightingEnabled_ && lighting_.model.twoSide;
  s.flatShading = flatShading_;
  // Unlit, with no colour in the vbo's vertex format (none given inside
  // glBegin/glEnd since the format was last reset), Mesa's fixed-function
  // fragment program reads the current colour, clamped, as a uniform
  // (STATE_CURRENT_ATTRIB_MAYBE_VP_CLAMPED), exactly, not as llvmpipe's
  // perspective interpolation would give it.
  s.uniformColor = flatShading_ || (!lightingEnabled_ && !colorVarying);
  s.fog = fog_;
  s.window = {vpScaleX_, vpTransX_, vpScaleY_, vpTransY_, static_cast<float>((depthFar_ - depthNear_) / 2.0),
              static_cast<float>((depthNear_ + depthFar_) / 2.0), fb().height()};
  s.drawRegion = drawRegion();
  s.scissoredFramebuffer = scissorEnabled_ ? fb().bounds().intersect(scissorBox_) : fb().bounds();
  s.windowMap = windowMap_;
  // s.clipPlanes and s.userPlanes: the block's, set by deriveBlockState.
  return s;
}

}  // namespace mpr
