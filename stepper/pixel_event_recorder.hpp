#pragma once
// Records what happened at chosen pixels while a script runs: every fragment
// that reached one (several per draw where primitives overlap, the shadow
// volume case) with its tests and stencil update, and every clear or
// accumulation return that changed one. `mpr step --pixel` records one
// pixel; the stepper page records the whole window.
//
// Use it from the script hooks: beforeCall(c) before each call, startPass()
// at each @pass, finish() after the last call. While it exists it owns the
// context's fragment observer; with no recorder the observer is unset and
// drawing pays nothing.
#include <cstdint>
#include <functional>
#include <vector>

#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"

namespace mpr {

struct PixelEvent {
  enum class Kind : std::uint8_t { Fragment, Change } kind = Kind::Fragment;
  int x = 0, y = 0;
  int pass = 0;                      // 0 is what comes before the first @pass
  const ScriptCommand* call = nullptr;
  int fragment = 0;                  // Fragment: its rank at this pixel within the call, from 1
  FragmentFate fate = FragmentFate::Written;  // Fragment only
  std::uint32_t stencilBefore = 0, stencilAfter = 0;
  std::uint32_t depthBefore = 0, depthIncoming = 0, depthAfter = 0;  // incoming: Fragment only
  Rgba8 colourBefore{}, colourAfter{};  // before: Change only (a fragment line shows the colour written)
};

class PixelEventRecorder {
 public:
  // `state` is the per-fragment state the call ran with (for the line's wording).
  using Sink = std::function<void(const PixelEvent&, const FragmentState& state)>;

  // Records the pixels of `region` (window coordinates, clipped to the window).
  PixelEventRecorder(GLContext& gl, PixelRect region, Sink sink);
  ~PixelEventRecorder();
  PixelEventRecorder(const PixelEventRecorder&) = delete;
  PixelEventRecorder& operator=(const PixelEventRecorder&) = delete;

  void beforeCall(const ScriptCommand& call);
  void startPass();
  void finish();
  int pass() const { return pass_; }

 private:
  struct Values {
    std::uint32_t stencil, depth;
    Rgba8 colour;
  };
  void closeCall();
  Values read(int x, int y) const;
  std::size_t slot(int x, int y) const {
    return static_cast<std::size_t>(y - region_.y0) * static_cast<std::size_t>(region_.x1 - region_.x0) +
           static_cast<std::size_t>(x - region_.x0);
  }

  GLContext& gl_;
  PixelRect region_;
  Sink sink_;
  int pass_ = 0;
  const ScriptCommand* call_ = nullptr;
  std::uint32_t callSerial_ = 0;
  const ScriptCommand* drawCall_ = nullptr;  // the last call that issued vertices: fragments are its
  std::uint32_t drawSerial_ = 0;
  int drawPass_ = 0;
  // Fragment ranks: rank_[slot] counts the fragments of call rankCall_[slot].
  std::vector<std::uint32_t> rankCall_;
  std::vector<int> rank_;
  // The region before a clear or accumulation call, to see what it changed.
  std::vector<Values> before_;
};

}  // namespace mpr
