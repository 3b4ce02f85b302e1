#pragma once
// The GL 1.x state machine of the emulated Iris pipeline: the spec's whole
// call set (spec/gl-script.md), executed on a Framebuffer. Methods take GL's
// own enum values (as <GL/gl.h> defines them), so a script, a test and the
// Mesa replayer speak the same numbers. GL errors follow GL: the call is
// ignored and the first error is kept until getError() reads it.
//
// For per-pixel tests the context also answers what is stored at a pixel:
//   gl.stencilAt(3, 4), gl.depthAt(x, y), gl.colorAt(x, y), gl.accumAt(x, y).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "framebuffer/accumulation.hpp"
#include "framebuffer/clear.hpp"
#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/fragment_pipeline.hpp"
#include "framebuffer/framebuffer.hpp"
#include "pipeline/draw/clipping.hpp"
#include "pipeline/draw/draw_snapshot.hpp"
#include "pipeline/draw/draw_stage.hpp"
#include "pipeline/draw/lighting.hpp"
#include "pipeline/draw/primitive_assembly.hpp"
#include "pipeline/draw/vertex_processing.hpp"
#include "pipeline/gl/matrix_stack.hpp"
#include "raster/fog.hpp"
#include "util/recent_results.hpp"
#include "util/vecmath.hpp"

namespace mpr {

using GLenumValue = std::uint32_t;

// Where Mesa 22.3 departs from GL 1.1 the emulated Iris follows GL 1.1; `mpr
// conform` replays a script once more with a departure emulated to tell
// which differences it explains (docs/explanation/mesa.md). Never set
// by a renderer.
enum MesaDeparture : unsigned {
  kColor3KeepsAlpha = 1u << 0,         // glColor3 keeps the alpha of an earlier glColor4 (color3_alpha.gls)
  kLightingUndividedEye = 1u << 1,     // vertices lit at the undivided eye xyz when w != 1 (lighting_vertex_w.gls)
  kFogHintIgnored = 1u << 2,           // GL_FOG_HINT GL_FASTEST fogs per fragment too (fog_hint_fastest.gls)
  kScalarCallVectorParam = 1u << 3,    // glFogf/glLightf/glMaterialf/glLightModelf take a vector pname as (v,0,0,0)
  kShininess0Attenuated = 1u << 4,     // shininess 0 with a spot or attenuated light: specular (N.L)^(N.L) (shininess0_attenuated.gls)
  kProjectiveNormalMatrix = 1u << 5,   // normals by the upper 3x3 of the modelview's 4x4 inverse (projective_normal_matrix.gls)
};

// The GL state machine: state, errors, Mesa's flush points and vertex-buffer
// (vbo) rules, glBegin/glVertex/glEnd. At each draw Mesa's vbo makes (a
// piece of a glBegin/glEnd block, a GL_QUADS draw closed at a flush) it
// processes the vertices, freezes what the draw reads of the state in a
// DrawSnapshot and hands both to its DrawStage (pipeline/draw/draw_stage.hpp),
// which owns the framebuffer and the row threads.
class GLContext {
 public:
  GLContext(int width, int height, const HardwareProfile& profile);
  GLContext(GLContext&&) = default;  // the draw stage first: it waits for its row threads

  // Readers see every call drawn: a GL_QUADS draw still open for merging
  // (see OpenQuadDraw) is closed first, as glReadPixels flushes in GL, and
  // the draws, clears and accumulations queued for the row threads have run.
  Framebuffer& framebuffer() { settle(); return fb(); }
  const Framebuffer& framebuffer() const { settle(); return fb(); }
  const PipelineCounters& counters() const { settle(); return draw_.counters(); }
  // Closes the open GL_QUADS draw now (what Mesa's FLUSH_VERTICES does).
  void flushVertices();
  // What glReadPixels does before it reads (a @snapshot in Mesa's replay):
  // the stored vertices drawn and the state validated, matrices analysed.
  void prepareRead() {
    flushVertices();
    analyseMatrices(true, true);
  }
  void closeQuadDraw();  // the open GL_QUADS draw only, not the vbo's flush (a glBegin of another mode)

  // --- per-pixel inspection for tests -----------------------------------
  std::uint32_t stencilAt(int x, int y) const { settle(); return fb().stencil(x, y); }
  std::uint32_t depthAt(int x, int y) const { settle(); return fb().depth(x, y); }
  Rgba8 colorAt(int x, int y) const { settle(); return fb().color(x, y); }
  std::array<std::int16_t, 4> accumAt(int x, int y) const;

  // --- errors -------------------------------------------------------------
  GLenumValue getError();  // GL_NO_ERROR (0) when none is pending

  // --- framebuffer and clears ----------------------------------------------
  void viewport(int x, int y, int w, int h);
  void scissor(int x, int y, int w, int h);
  void clearColor(float r, float g, float b, float a);
  void clearDepth(double d);
  void clearStencil(int s);
  void clearAccum(float r, float g, float b, float a);
  void clear(std::uint32_t mask);
  void colorMask(bool r, bool g, bool b, bool a);
  void depthMask(bool flag);
  void stencilMask(std::uint32_t mask);
  // The quads waiting to be drawn go first; inside glBegin/glEnd they are
  // GL_INVALID_OPERATION (as Mesa).
  void finish() {
    if (checkOutsideBeginEnd()) flushVertices();
  }
  void flush() {
    if (checkOutsideBeginEnd()) flushVertices();
  }

  // --- per-fragment state ---------------------------------------------------
  void enable(GLenumValue cap) { setCapability(cap, true); }
  void disable(GLenumValue cap) { setCapability(cap, false); }
  bool isEnabled(GLenumValue cap) const;
  void stencilFunc(GLenumValue func, int ref, std::uint32_t mask);
  void stencilOp(GLenumValue sfail, GLenumValue dpfail, GLenumValue dppass);
  void depthFunc(GLenumValue func);
  void depthRange(double n, double f);
  void blendFunc(GLenumValue src, GLenumValue dst);
  void alphaFunc(GLenumValue func, float ref);
  void cullFace(GLenumValue mode);
  void frontFace(GLenumValue mode);
  void shadeModel(GLenumValue mode);
  void fogf(GLenumValue pname, float param);
  void fogi(GLenumValue pname, int param) { fogf(pname, static_cast<float>(param)); }
  void fogfv(GLenumValue pname, const float* params, int count);
  void hint(GLenumValue target, GLenumValue mode);

  // --- transform --------------------------------------------------------------
  void matrixMode(GLenumValue mode);
  void loadIdentity();
  void loadMatrix(const float m[16]);
  void multMatrix(const float m[16]);
  void pushMatrix();
  void popMatrix();
  void translate(float x, float y, float z);
  void rotate(float angle, float x, float y, float z);
  void scale(float x, float y, float z);
  void frustum(double l, double r, double b, double t, double n, double f);
  void ortho(double l, double r, double b, double t, double n, double f);
  void perspective(double fovy, double aspect, double zNear, double zFar);  // gluPerspective
  void lookAt(double ex, double ey, double ez, double cx, double cy, double cz, double ux, double uy,
              double uz);  // gluLookAt
  void clipPlane(GLenumValue plane, const double eq[4]);
  const Mat4& modelview() const { return modelview_.top(); }
  const Mat4& projection() const { return projection_.top(); }

  // --- lighting and colour -----------------------------------------------------
  void lightf(GLenumValue light, GLenumValue pname, float param);
  void lightfv(GLenumValue light, GLenumValue pname, const float* params, int count);
  void lightModelf(GLenumValue pname, float param);
  void lightModelfv(GLenumValue pname, const float* params, int count);
  void lightModeli(GLenumValue pname, int param) { lightModelf(pname, static_cast<float>(param)); }
  void materialf(GLenumValue face, GLenumValue pname, float param);
  void materialfv(GLenumValue face, GLenumValue pname, const float* params, int count);
  void colorMaterial(GLenumValue face, GLenumValue mode);
  void color3f(float r, float g, float b);  // alpha 1 (GL 1.1 section 2.7)
  void color4f(float r, float g, float b, float a);
  void color4ub(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a);
  void normal3f(float x, float y, float z);

  // --- geometry -------------------------------------------------------------------
  void begin(GLenumValue mode);
  void end();
  // size: the call's arity (glVertex2f 2, glVertex3f 3, glVertex4f 4), which
  // Mesa's vbo keeps in its vertex format (see vboAttribute).
  void vertex4f(float x, float y, float z, float w, int size = 4);
  void rectf(float x1, float y1, float x2, float y2);
  bool insideBeginEnd() const { return inBegin_; }

  // --- accumulation --------------------------------------------------------------
  void accum(GLenumValue op, float value);

  // --- state a pass stepper or test reads ----------------------------------------
  const FragmentState& fragmentState() const { return frag_; }
  const FogState& fogState() const { return fog_; }
  PixelRect scissorBox() const { return scissorBox_; }
  bool scissorEnabled() const { return scissorEnabled_; }
  PixelRect viewportBox() const { return viewportBox_; }
  GLenumValue cullFaceMode() const { return cullMode_; }
  GLenumValue frontFaceMode() const { return frontFace_; }
  bool flatShading() const { return flatShading_; }
  std::array<double, 2> depthRangeValues() const { return {depthNear_, depthFar_}; }

  // --- the end-of-pipeline map (an MPR extension, not a GL call) ------------
  // The 1994 paper's wish ("Refractions"): "in hardware that supports
  // user-defined transforms, this transform can be inserted directly at the
  // end of the rendering pipeline". A 3x3 projective map of normalised device
  // x, y in the paper's row-vector form, [u v q] = [x y 1] M (glm: column k
  // gives output k), applied after the perspective divide and before the
  // viewport; depth is kept. See its semantics in pipeline/draw/triangle_setup.cpp.
  // Not part of the GL state (no glGet, not saved by glPush/Pop): a stage of
  // the emulated hardware that a renderer switches on and off.
  void setWindowMap(const std::optional<glm::mat3>& map) {
    flushVertices();
    windowMap_ = map;
  }
  const std::optional<glm::mat3>& windowMap() const { return windowMap_; }

  // Emulates the given MesaDeparture bits (for `mpr conform` only).
  void emulateMesaDepartures(unsigned departures) { departures_ = departures; }

  // Observes every fragment that reaches the per-fragment tests; costs nothing
  // when unset.
  FragmentObserver fragmentObserver;

  // Threads the framebuffer's rows are shared out over (DrawStage::setThreads:
  // the bytes, counts and observed histories are the same at any count).
  void setThreads(int threads) { draw_.setThreads(threads); }
  int threads() const { return draw_.threads(); }
  static constexpr std::size_t kTrianglesPerQueuedDraw = DrawStage::kTrianglesPerQueuedDraw;

 private:
  bool clearByQuad(const ClearBuffers& which) const;

  using Vertex = CapturedVertex;  // what glVertex captures, processed at glEnd
  RecentResults<Vertex, ClipVertex, 256> recentVertices_;  // end()'s processed vertices of the piece

  // The GL_QUADS draw Mesa's vbo is building: consecutive glBegin(GL_QUADS)
  // blocks with nothing but vertex attributes between them become one draw,
  // and when any vertex of that draw lies outside a clip plane, the draw
  // module splits all its quads (0, 1, 3) (1, 2, 3). Until a vertex outside
  // is seen, the quads wait here (drawn (0, 1, 2) (0, 2, 3) when the draw is
  // closed); once one is seen, every quad of the draw is drawn at its glEnd.
  struct OpenQuadDraw {
    bool open = false;
    bool clipped = false;              // a vertex of the draw lies outside a plane
    std::size_t vertexCount = 0;       // in the whole draw so far
    std::vector<ClipVertex> waiting;   // processed, not yet drawn (only while !clipped)
    bool colorVarying = false;         // the colour is in the vbo's vertex format of the draw
  };

  // Mesa's vbo vertex format (vbo_exec_api.c): the size of each per-vertex
  // attribute in its vertex buffer, 0 until first seen after a flush. An
  // attribute that grows (vbo_exec_fixup_vertex) makes the vbo draw what it
  // holds and go on in a new buffer (vbo_exec_wrap_upgrade_vertex): inside
  // glBegin/glEnd the block is cut there, the unfinished primitive's vertices
  // copied on (vbo_copy_vertices). Each piece is a draw of its own, which
  // decides which quads share the draw module's clipping decision.
  enum VboSlot : int { kVboPosition, kVboColor, kVboNormal, kVboMaterial, kVboSlots = kVboMaterial + 10 };
  static constexpr int kShininessSlot = 4;  // a side's shininess among its five vbo material slots
  // Bit 0: the front shininess is in the vbo's vertex format; bit 1: the back's.
  std::uint8_t shininessVarying() const;
  bool shininessKeyZero(std::uint8_t varying) const;
  void vboAttribute(int slot, int size);
  void copyToCurrent();        // vbo_exec_copy_to_current
  void copyAndResetFormat();   // vbo_exec_FlushVertices_internal: copyToCurrent, then vbo_reset_all_attr
  void setCurrentColor(const Vec4& c);
  void drawQuadsPiece(std::vector<ClipVertex> piece, bool colorVarying);  // one GL_QUADS draw piece

  void setError(GLenumValue e);
  bool checkOutsideBeginEnd();  // GL_INVALID_OPERATION inside glBegin/glEnd; no flush
  // Mesa's setters return early when a call leaves their state as it is and
  // flush the stored vertices (FLUSH_VERTICES) before they change it: an open
  // GL_QUADS draw stays open over a call that changes nothing (measured
  // against llvmpipe call by call: tests/conformance/repro/redundant_state_quads.gls).
  bool changing(bool unchanged) {
    if (unchanged) return false;
    flushVertices();
    return true;
  }
  template <typename T, typename V>
  void setIfChanged(T& stored, const V& value) {  // Mesa's compare, flush, store
    if (changing(stored == value)) stored = value;
  }
  void setCapability(GLenumValue cap, bool on);
  MatrixStack& currentStack();
  void setTop(const Mat4& m, unsigned addedFlags);  // flushes, replaces the top, adds Mesa's flags
  void multiplyTop(const Mat4& m);                  // glMultMatrix: nothing at all for the identity
  // _math_matrix_analyse of the tops where Mesa validates its state (glBegin,
  // glAccum, glReadPixels; not glClear) or reads an inverse (glClipPlane,
  // glEnable of a clip plane, glLightfv of a spot direction).
  void analyseMatrices(bool modelview, bool projection);
  void afterMatrixChange();
  void applyColorMaterial();
  // glEnd's steps: the matrices and clip planes of the block
  // (deriveBlockState), the pieces Mesa's vbo cut it into (vboPieces), the
  // lighting its vertices share (blockLighting), then each piece processed
  // (processPiece: pipeline/draw/vertex_processing.hpp on the piece's frozen
  // VertexSnapshot) and handed on (drawPiece): the whole block as one piece
  // where cutting it changes nothing drawn, else piece by piece with the
  // vertices the vbo carries over (drawInPieces).
  struct VboPiece {
    std::size_t end;      // vertices_ index where the piece stops
    bool shininessZero;   // Mesa's material_shininess_is_zero for its draw
    bool colorVarying;    // the colour is in its vertex format
  };
  void deriveBlockState();
  std::vector<VboPiece> vboPieces();
  LightingState blockLighting() const;
  // The first `count` of `indices` (vertices_ indices; all of vertices_
  // when null), lit by the program a piece's draw selects.
  std::vector<ClipVertex> processPiece(const std::size_t* indices, std::size_t count, bool shininessZero,
                                       LightingState& lighting);
  VertexSnapshot vertexSnapshot() const;  // the state processVertex reads, for the piece about to be processed
  void drawPiece(std::vector<ClipVertex> processed, bool colorVarying, bool last);
  void drawInPieces(const std::vector<VboPiece>& pieces, LightingState& lighting);
  void settle() const;  // closes the open quad draw and drains the queue (a reader sees it drawn)
  void drain() const { draw_.drain(); }  // waits for the row threads' queue
  PixelRect drawRegion() const;  // viewport ∩ scissor ∩ window
  // The state a draw reads, frozen for the draw handed on now (the clip
  // planes as end() derived them for its block); `colorVarying`: the colour
  // is in the vertex format of the draw.
  const DrawSnapshot& drawSnapshot(bool colorVarying);
  Framebuffer& fb() { return draw_.framebuffer(); }
  const Framebuffer& fb() const { return draw_.framebuffer(); }

  // Values as Mesa's setters store and compare them, where MPR keeps them
  // converted (a stencil mask at the buffer's width, a clamped reference):
  // Mesa compares the call's raw arguments with these (stencil.c, blend.c).
  struct MesaSetterValues {
    int stencilRef = 0;
    std::uint32_t stencilValueMask = 0xFF, stencilWriteMask = 0xFF;  // _mesa_init_stencil
    float alphaRef = 0.0f;                                              // AlphaRefUnclamped
    std::array<int, 4> scissor{};                                       // x, y, width, height
    std::array<int, 4> viewport{};                                      // sizes clamped to the maximum
    float fogIndex = 0.0f;                                              // colour-index mode only
    // GL_FOG_HINT, GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_, GL_LINE_, GL_POLYGON_SMOOTH_HINT
    std::array<GLenumValue, 5> hints{0x1100, 0x1100, 0x1100, 0x1100, 0x1100};  // GL_DONT_CARE
  };

  // First: moved first, it waits for what its row threads still draw.
  DrawStage draw_;
  // Refilled for each draw handed on (drawSnapshot); its clip planes are
  // the block's, derived at glEnd (deriveBlockState) and kept for the
  // draws of that block, the GL_QUADS draw closed later included.
  DrawSnapshot drawSnapshot_;
  MesaSetterValues setterValues_;
  GLenumValue error_ = 0;

  // framebuffer state
  PixelRect viewportBox_;
  float vpScaleX_, vpScaleY_, vpTransX_, vpTransY_;
  double depthNear_ = 0.0, depthFar_ = 1.0;
  PixelRect scissorBox_;
  bool scissorEnabled_ = false;
  ClearValues clearValues_;
  std::uint32_t quadClearDepth_ = 0;  // the depth a clear drawn as a quad stores (clearByQuad)
  std::array<float, 4> clearAccumValue_{0, 0, 0, 0};
  FragmentState frag_;

  // rasterization state
  bool cullEnabled_ = false;
  GLenumValue cullMode_;
  GLenumValue frontFace_;
  bool flatShading_ = false;
  bool ditherEnabled_ = true;

  // transform state
  MatrixStack modelview_, projection_;
  GLenumValue matrixMode_;
  std::array<ClipPlane, 6> clipPlanesEye_{};
  std::array<bool, 6> clipPlaneEnabled_{};
  bool normalize_ = false;

  // lighting, colour, fog
  bool lightingEnabled_ = false;
  LightingState lighting_;
  bool colorMaterialEnabled_ = false;
  bool settingTrackedMaterial_ = false;  // applyColorMaterial's own materialfv
  std::array<std::uint8_t, kVboSlots> vboSize_{};  // Mesa's vbo vertex format (vboAttribute)
  std::array<Material, 2> vboMaterial_;             // the material values the vbo holds (its slots in vboSize_)
  Vec4 copiedColor_{1, 1, 1, 1};                    // Mesa's ctx->Current colour: the vbo's, as last copied
  bool vboStored_ = false;                          // a glBegin since the last flush (FLUSH_STORED_VERTICES)
  std::size_t vboVertexCount_ = 0;                  // vertices in the vbo's buffer since it was last drawn
  std::size_t pieceVertexCount_ = 0;                // of them, this block's since the vbo last cut it
  struct BlockWrap {
    std::size_t vertex;              // where the vbo cut this block (vertices_ index)
    std::uint8_t shininessVarying;   // shininessVarying() of the format the piece before is drawn with
    bool colorVarying;               // the colour was in that format
  };
  std::vector<BlockWrap> blockWraps_;
  GLenumValue colorMaterialFace_, colorMaterialMode_;
  Vec4 currentColor_{1, 1, 1, 1};
  Vec3 currentNormal_{0, 0, 1};
  FogState fog_;

  // begin/end
  bool inBegin_ = false;
  PrimitiveType primitive_ = PrimitiveType::Triangles;
  std::vector<Vertex> vertices_;
  std::vector<std::array<Material, 2>> blockMaterials_;  // glMaterial inside glBegin/glEnd (GL 1.1 section 2.6.3)
  bool blockMaterialUsed_ = false;                       // a vertex refers to blockMaterials_.back()
  OpenQuadDraw quadDraw_;
  // per-draw derived state, computed at glEnd
  Mat4 mvp_;
  glm::mat3 normalMatrix_;
  std::optional<glm::mat3> windowMap_;
  unsigned departures_ = 0;  // MesaDeparture bits
};

}  // namespace mpr
