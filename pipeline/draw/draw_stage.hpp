#pragma once
// The draw stage: everything from a draw's processed vertices down to the
// framebuffer, reading the GL state only through the draw's frozen
// DrawSnapshot. In the order a triangle meets it:
//   draw_stage.cpp      primitive assembly, the clip route and the early
//                       cull (triangle_decisions.hpp), Mesa's draw module's
//                       quad-strip order;
//   triangle_setup.cpp  llvmpipe's set-up: an unclipped (or MPR-clipped)
//                       triangle, the fan of a triangle draw clips, a fan
//                       triangle whose steps wrap (llvmpipe's tiles);
//   row_drawing.cpp     binning to rows and the row threads, the row loops,
//                       span submission to the per-fragment operations.
// It owns the framebuffer it draws into (and the row threads that draw
// it), so that queued work and the pixels it writes live and move together.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "framebuffer/framebuffer.hpp"
#include "pipeline/draw/draw_snapshot.hpp"
#include "pipeline/draw/primitive_assembly.hpp"
#include "raster/llvmpipe_depth.hpp"
#include "raster/span_shading.hpp"
#include "raster/triangle_rasterizer.hpp"
#include "util/row_queue.hpp"
#include "util/vector_pool.hpp"

namespace mpr {

// Counters a renderer reports with --stats and a benchmark divides by time.
struct PipelineCounters {
  std::uint64_t triangles = 0;        // after primitive assembly
  std::uint64_t trianglesDrawn = 0;   // survived clipping and culling
  std::uint64_t fragmentsTested = 0;  // covered pixels entering the per-fragment tests
  std::uint64_t fragmentsWritten = 0; // passed every test
};

// The fragments a share of a draw tested and wrote.
struct FragmentTally {
  std::uint64_t tested = 0, written = 0;
};

namespace detail {
// A draw stage's row threads (DrawStage::setThreads) and what each has
// counted since the stage last drained them (thread k writes rowTallies[k]
// only; apart, so no two share a cache line). A base of the stage: queued
// work refers to the stage's members, so a stage being moved waits for it
// here, before any member moves.
struct RowThreads {
  struct alignas(64) RowTally {
    FragmentTally tally;
  };
  std::vector<RowTally> rowTallies;
  std::unique_ptr<RowQueue> rowQueue;

  RowThreads() = default;
  RowThreads(RowThreads&& other) {
    if (other.rowQueue) other.rowQueue->wait();
    rowTallies = std::move(other.rowTallies);
    rowQueue = std::move(other.rowQueue);
  }
  RowThreads& operator=(RowThreads&&) = delete;
};
}  // namespace detail

class DrawStage : private detail::RowThreads {
 public:
  DrawStage(int width, int height, const HardwareProfile& profile) : fb_(width, height, profile) {}
  DrawStage(DrawStage&&) = default;  // after RowThreads has drained the queue
  // Stops the row threads (after what is queued) while the framebuffer lives.
  ~DrawStage() { rowQueue.reset(); }

  // One draw of Mesa's vbo: `vertices` processed (clip coordinates and
  // varyings), assembled as `type`. Quads are split (0, 1, 2) (0, 2, 3), or
  // with `quadsOtherDiagonal` (0, 1, 3) (1, 2, 3), as Mesa's draw module
  // splits them when it runs its pipeline: the caller (Mesa's vbo, which
  // merges GL_QUADS blocks into one draw) decides, asking runsDrawPipeline.
  void draw(const DrawSnapshot& s, PrimitiveType type, std::span<const ClipVertex> vertices,
            bool quadsOtherDiagonal = false);
  // Whether Mesa's draw module runs its pipeline for a draw of these
  // vertices (only the first `count`: the draw trimmed to whole primitives):
  // whether any lies outside a plane of its clip mask.
  static bool runsDrawPipeline(const DrawSnapshot& s, std::span<const ClipVertex> vertices, std::size_t count);

  // The framebuffer as it stands: what is queued for the row threads may
  // not have reached it yet (drain() first to read it).
  Framebuffer& framebuffer() { return fb_; }
  const Framebuffer& framebuffer() const { return fb_; }
  // The counters, the row threads' fragments summed in at the last drain().
  const PipelineCounters& counters() const { return counters_; }
  void drain() const;  // waits for the row threads' queue; their fragment counts into the counters

  // Threads the framebuffer's rows are shared out over (util/row_queue.hpp,
  // drawDeferred). With more than one, draws, clears and accumulations are
  // queued and run behind the calls, thread k drawing the rows y with
  // y mod threads == k of each in submission order; the calls go on
  // (transform, lighting, set-up) while they run, and a reader waits for
  // them. Every pixel still sees its fragments in the same order, so the
  // bytes, counts and observed histories are the same at any count (with an
  // observer set, every triangle is drawn on the calling thread as it comes).
  // Default 1: everything on the calling thread.
  void setThreads(int threads);
  int threads() const { return rowQueue ? rowQueue->threads() : 1; }
  // With row threads, a draw is queued in pieces of at most this many
  // triangles: the threads start on the first while the rest are set up,
  // and the set-ups in flight stay bounded however long the draw.
  static constexpr std::size_t kTrianglesPerQueuedDraw = 256;
  // work(fb, rows) over the region's rows: queued for the row threads, one
  // row at a time, or here without them (clears and accumulation: a pixel's
  // result is its own). `work` is kept until it has run: it holds what it needs.
  void forRowBlocks(const PixelRect& region, std::function<void(Framebuffer&, const PixelRect&)> work);

 private:
  // --- draw_stage.cpp: assembly, clip route, early cull -----------------------
  void drawTriangle(const DrawSnapshot& s, const std::array<ClipVertex, 3>& tri, const LlvmpipeDepth& depth);
  // Whether drawTriangle would take `tri` unclipped to rasterizeClippedTriangle
  // and drop it there at the facing test (culled, no area, or a position not
  // finite): then nothing of its set-up is needed. Without the window map.
  bool culledBeforeSetUp(const DrawSnapshot& s, const std::array<ClipVertex, 3>& tri) const;

  // --- triangle_setup.cpp: llvmpipe's set-up ------------------------------------
  void rasterizeClippedTriangle(const DrawSnapshot& s, const ClipVertex& a, const ClipVertex& b,
                                const ClipVertex& c, const LlvmpipeDepth& depth);
  // A triangle Mesa's draw module clips: llvmpipe's fan of it, each pixel its
  // fixed-point edges cover, its depth and colour from that fan triangle.
  void rasterizeLlvmpipeFan(const DrawSnapshot& s, const LlvmpipeDepth& depth);

  // --- row_drawing.cpp: rows, threads, spans -------------------------------------
  // What a draw's fragments go through: the per-fragment state and the
  // function chosen for it, and the observer that sees each one (null: none).
  // A queued draw holds its own copy of the state.
  struct DrawState {
    const FragmentState& frag;
    FragmentPipeline pipeline;
    const FragmentObserver* observer;
  };
  // A triangle set up for drawing: what its rows need, and the rows.
  struct ClippedTriangleRows {
    std::array<SnappedVertex, 3> snapped;
    PixelBounds bounds;
    TriangleShading shading;
  };
  struct FanTriangleRows {  // one triangle of llvmpipe's fan
    FanShading shading;
    LlvmpipeDepth::Triangle triangle;
    std::int64_t x0, x1, y0, y1;  // columns, and rows in llvmpipe's y-down order
    // llvmpipe's draw region (framebuffer within the scissor box), inclusive,
    // y-down: for a triangle whose steps wrap (LlvmpipeTileRaster).
    std::array<int, 4> llvmpipeRegion{};
  };
  struct DeferredTriangle {  // the index of its set-up in deferredClipped_ or deferredFan_
    std::uint32_t index;
    bool fan;
  };
  // Starts a draw: deferring with row threads and no observer.
  void beginDraw(const DrawSnapshot& s) { deferring_ = rowQueue != nullptr && !s.observer; }
  void endDraw(const DrawSnapshot& s) {
    drawDeferred(s);
    deferring_ = false;
  }
  // Before a triangle's set-up: a long deferred draw is queued a piece at a
  // time; `remaining` triangles of the draw are still to come.
  void beforeTriangle(const DrawSnapshot& s, std::size_t remaining);
  // A set-up drawn now, after what the draw deferred, on the row threads (or
  // here without them or with an observer), waited for.
  template <typename Rows>  // ClippedTriangleRows or FanTriangleRows (row_drawing.cpp instantiates both)
  void drawNow(const DrawSnapshot& s, const Rows& job);
  // A set-up kept for drawDeferred: the storage deferredClipped_'s next
  // element, or a fan triangle copied in.
  ClippedTriangleRows& deferClipped();
  void defer(const FanTriangleRows& job);
  void drawDeferred(const DrawSnapshot& s);  // the deferred triangles, in order, queued for the row threads
  // The rows y with y mod stride == phase of a set-up triangle.
  // (fragments: the share's span to fill, scratch kept between triangles.)
  void drawRows(const ClippedTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride, int phase,
                FragmentSpan& fragments);
  void drawRows(const FanTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride, int phase,
                FragmentSpan& fragments);
  // The per-fragment operations, counted, observed.
  void submitFragment(Fragment& f, const DrawState& state, FragmentTally& tally);
  // The same for a span of fragments: one call of the state's span function,
  // or fragment by fragment in the span's order when it is observed.
  void submitSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally);
  // Before a span is shaded: true when the state's stencil test, taken first,
  // fails for every pixel of it (x, y, count); those are then done, counted
  // as tested (FragmentPipeline::stencilRejectsAll). Never for an observed draw.
  bool stencilRejectsSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally);
  void addTally(const FragmentTally& tally) const;

  Framebuffer fb_;
  mutable PipelineCounters counters_;  // fragments summed in by drain()
  bool deferring_ = false;             // this draw's triangles are kept for drawDeferred
  std::vector<DeferredTriangle> deferred_;  // in submission order
  std::vector<ClippedTriangleRows> deferredClipped_;
  std::vector<FanTriangleRows> deferredFan_;
  // deferredClipped_'s storage after its draw has run, for a later draw
  // (shared: the row thread that ran the draw last hands it back).
  std::shared_ptr<VectorPool<ClippedTriangleRows>> spentClipped_ =
      std::make_shared<VectorPool<ClippedTriangleRows>>(4);
};

}  // namespace mpr
