// DrawStage: binning to rows and the row threads, the row loops of a
// set-up triangle, and span submission to the per-fragment operations.
// The per-span calls (stencilRejectsSpan, shadeSpan, submitSpan) stay in
// this one translation unit with the row loops, where they inline.
#include <algorithm>
#include <utility>

#include "pipeline/draw/draw_stage.hpp"
#include "raster/llvmpipe_row_spans.hpp"
#include "raster/llvmpipe_tile_raster.hpp"
#include "util/check.hpp"

namespace mpr {

void DrawStage::setThreads(int threads) {
  drain();
  rowQueue.reset();  // its threads stopped before rowTallies changes
  rowTallies.assign(threads > 1 ? static_cast<std::size_t>(threads) : 0, RowTally{});
  if (threads > 1) rowQueue = std::make_unique<RowQueue>(threads);
}

void DrawStage::drain() const {
  if (!rowQueue) return;
  rowQueue->wait();
  // Sums: the same whichever thread counted what.
  for (const RowTally& t : rowTallies) addTally(t.tally);
  for (RowTally& t : const_cast<DrawStage*>(this)->rowTallies) t.tally = {};
}

void DrawStage::addTally(const FragmentTally& tally) const {
  counters_.fragmentsTested += tally.tested;
  counters_.fragmentsWritten += tally.written;
}

void DrawStage::forRowBlocks(const PixelRect& region, std::function<void(Framebuffer&, const PixelRect&)> work) {
  MPR_DCHECK(region.empty() ||
             (region.x0 >= 0 && region.y0 >= 0 && region.x1 <= fb_.width() && region.y1 <= fb_.height()));
  if (!rowQueue) return work(fb_, region);
  if (region.empty()) return;
  // Every pixel's result depends on that pixel alone: row thread k takes
  // the rows y with y mod n == k, the rows it draws (drawDeferred), so the
  // pixel's clears, draws and accumulations stay in the order of the calls.
  const int n = rowQueue->threads();
  rowQueue->push([this, region, work = std::move(work), n](int k) {
    for (int y = region.y0 + ((k - region.y0) % n + n) % n; y < region.y1; y += n)
      work(fb_, PixelRect{region.x0, y, region.x1, y + 1});
  });
}

void DrawStage::beforeTriangle(const DrawSnapshot& s, std::size_t remaining) {
  if (!deferring_) return;
  // A long draw is queued a piece at a time, so the row threads start on
  // its first triangles while the rest are being set up (a draw of the
  // bathroom trace has up to 4 000).
  if (deferred_.size() >= kTrianglesPerQueuedDraw) drawDeferred(s);
  // drawDeferred hands these vectors to the queued piece, so each piece
  // starts them empty: sized once for it (a triangle is one set-up unless
  // MPR's clipper cuts it), not grown by doubling, which copied every set-up
  // so far (half of the set-up's time on the bathroom trace).
  if (deferred_.empty()) {
    const std::size_t piece = std::min(remaining, kTrianglesPerQueuedDraw);
    deferred_.reserve(piece);
    deferredClipped_.reserve(piece);
  }
}

// Drawn now: the share k of n on the row threads after what is queued, and
// waited for (`job` is this call's set-up); without threads, or with an
// observer set, all of it here. The tallies summed into the counters.
template <typename Rows>
void DrawStage::drawNow(const DrawSnapshot& s, const Rows& job) {
  if (deferring_) drawDeferred(s);  // what the draw kept goes first
  const DrawState state{s.frag, s.pipeline, s.observer};
  if (rowQueue && !s.observer) {
    const int n = rowQueue->threads();
    rowQueue->push([&, n](int k) {
      FragmentSpan fragments;  // per share: shares run at once
      drawRows(job, state, rowTallies[static_cast<std::size_t>(k)].tally, n, k, fragments);
    });
    return drain();
  }
  drain();  // what is queued goes first
  FragmentTally tally;
  FragmentSpan fragments;
  drawRows(job, state, tally, 1, 0, fragments);
  addTally(tally);
}
template void DrawStage::drawNow(const DrawSnapshot&, const ClippedTriangleRows&);
template void DrawStage::drawNow(const DrawSnapshot&, const FanTriangleRows&);

DrawStage::ClippedTriangleRows& DrawStage::deferClipped() {
  deferred_.push_back({static_cast<std::uint32_t>(deferredClipped_.size()), false});
  return deferredClipped_.emplace_back();
}

inline void DrawStage::submitFragment(Fragment& f, const DrawState& state, FragmentTally& tally) {
  ++tally.tested;
  if (state.observer) {
    const int x = f.x, y = f.y;
    FragmentEvent ev{x, y, fb_.stencil(x, y), 0, fb_.depth(x, y), f.depth, FragmentFate::Written, {}};
    ev.fate = state.pipeline.fragment(state.frag, fb_, f);
    ev.stencilAfter = fb_.stencil(x, y);
    ev.colorAfter = fb_.color(x, y);
    if (ev.fate == FragmentFate::Written) ++tally.written;
    (*state.observer)(ev);
    return;
  }
  if (state.pipeline.fragment(state.frag, fb_, f) == FragmentFate::Written) ++tally.written;
}

namespace {
// A span a row loop hands on: one row's pixels, all within the framebuffer.
[[maybe_unused]] inline bool spanInside(const FragmentSpan& span, const Framebuffer& fb) {
  return span.count > 0 && span.count <= FragmentSpan::kCapacity && span.x >= 0 && span.y >= 0 &&
         span.y < fb.height() && span.x + span.count <= fb.width();
}
}  // namespace

inline bool DrawStage::stencilRejectsSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally) {
  MPR_DCHECK(spanInside(span, fb_));
  if (!state.pipeline.stencilRejectsAll || state.observer) return false;  // observed: each fragment seen whole
  if (!state.pipeline.stencilRejectsAll(state.frag, fb_, span.x, span.y, span.count)) return false;
  tally.tested += static_cast<std::uint64_t>(span.count);
  return true;
}

inline void DrawStage::submitSpan(const FragmentSpan& span, const DrawState& state, FragmentTally& tally) {
  MPR_DCHECK(spanInside(span, fb_));
  if (state.observer) {  // fragment by fragment, in the span's order, each one seen
    for (int i = 0; i < span.count; ++i) {
      Fragment f{span.x + i, span.y, span.depth[i], span.color[i], span.alpha[i]};
      submitFragment(f, state, tally);
    }
    return;
  }
  tally.tested += static_cast<std::uint64_t>(span.count);
  tally.written += state.pipeline.span(state.frag, fb_, span);
}

void DrawStage::drawRows(const ClippedTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride,
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

void DrawStage::drawRows(const FanTriangleRows& job, const DrawState& state, FragmentTally& tally, int stride,
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
void DrawStage::defer(const FanTriangleRows& job) {
  deferred_.push_back({static_cast<std::uint32_t>(deferredFan_.size()), true});
  deferredFan_.push_back(job);
}

void DrawStage::drawDeferred(const DrawSnapshot& s) {
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
  std::shared_ptr<Draw> draw(new Draw{s.frag, s.pipeline, s.fog, std::move(deferred_), {}, {}},
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
    const DrawState state{draw->frag, draw->pipeline, nullptr};
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
