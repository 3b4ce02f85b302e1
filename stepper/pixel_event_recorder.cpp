#include "stepper/pixel_event_recorder.hpp"

namespace mpr {
namespace {

// Only these calls change pixels without fragments; every other change is a
// fragment, which the observer reports.
bool writesWithoutFragments(const ScriptCommand& c) { return c.call == GLCall::Clear || c.call == GLCall::Accum; }

// The calls whose vertices make fragments. A GL_QUADS draw may be drawn at
// a later call (Mesa's vbo keeps it open over calls that change no state,
// GLContext::drawQuadsPiece); its fragments belong to the call that issued it.
bool issuesVertices(const ScriptCommand& c) { return c.call == GLCall::End || c.call == GLCall::Rectf; }

}  // namespace

PixelEventRecorder::PixelEventRecorder(GLContext& gl, PixelRect region, Sink sink)
    : gl_(gl), region_(region.intersect(gl.framebuffer().bounds())), sink_(std::move(sink)) {
  if (region_.empty()) region_ = {};
  const std::size_t n = static_cast<std::size_t>(region_.x1 - region_.x0) * static_cast<std::size_t>(region_.y1 - region_.y0);
  rankCall_.assign(n, 0);
  rank_.assign(n, 0);
  gl_.fragmentObserver = [this](const FragmentEvent& e) {
    if (e.x < region_.x0 || e.x >= region_.x1 || e.y < region_.y0 || e.y >= region_.y1 || !drawCall_) return;
    const std::size_t s = slot(e.x, e.y);
    if (rankCall_[s] != drawSerial_) {
      rankCall_[s] = drawSerial_;
      rank_[s] = 0;
    }
    PixelEvent p;
    p.kind = PixelEvent::Kind::Fragment;
    p.x = e.x;
    p.y = e.y;
    p.pass = drawPass_;
    p.call = drawCall_;
    p.fragment = ++rank_[s];
    p.fate = e.fate;
    p.stencilBefore = e.stencilBefore;
    p.stencilAfter = e.stencilAfter;
    p.depthBefore = e.depthBefore;
    p.depthIncoming = e.depthIncoming;
    p.depthAfter = gl_.depthAt(e.x, e.y);
    p.colourAfter = e.colorAfter;
    sink_(p, gl_.fragmentState());
  };
}

PixelEventRecorder::~PixelEventRecorder() { gl_.fragmentObserver = nullptr; }

PixelEventRecorder::Values PixelEventRecorder::read(int x, int y) const {
  return {gl_.stencilAt(x, y), gl_.depthAt(x, y), gl_.colorAt(x, y)};
}

void PixelEventRecorder::beforeCall(const ScriptCommand& call) {
  closeCall();
  call_ = &call;
  ++callSerial_;
  if (issuesVertices(call)) {
    drawCall_ = &call;
    drawSerial_ = callSerial_;
    drawPass_ = pass_;
  }
  if (!writesWithoutFragments(call)) return;
  before_.clear();
  before_.reserve(rank_.size());
  for (int y = region_.y0; y < region_.y1; ++y)
    for (int x = region_.x0; x < region_.x1; ++x) before_.push_back(read(x, y));
}

void PixelEventRecorder::closeCall() {
  if (!call_ || !writesWithoutFragments(*call_)) return;
  PixelEvent p;
  p.kind = PixelEvent::Kind::Change;
  p.pass = pass_;
  p.call = call_;
  for (int y = region_.y0; y < region_.y1; ++y)
    for (int x = region_.x0; x < region_.x1; ++x) {
      const Values& b = before_[slot(x, y)];
      const Values a = read(x, y);
      if (a.stencil == b.stencil && a.depth == b.depth && a.colour == b.colour) continue;
      p.x = x;
      p.y = y;
      p.stencilBefore = b.stencil;
      p.stencilAfter = a.stencil;
      p.depthBefore = b.depth;
      p.depthAfter = a.depth;
      p.colourBefore = b.colour;
      p.colourAfter = a.colour;
      sink_(p, gl_.fragmentState());
    }
  call_ = nullptr;
}

void PixelEventRecorder::startPass() {
  closeCall();
  call_ = nullptr;
  ++pass_;
}

void PixelEventRecorder::finish() {
  closeCall();
  call_ = nullptr;
}

}  // namespace mpr
