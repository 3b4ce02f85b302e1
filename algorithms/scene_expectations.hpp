#pragma once
// A scene's `expect:` list (docs/scene-format.md, "Expectations"): each entry
// is a probe (framebuffer/script_probe.hpp, the GL scripts' @expect) read at
// a named point of the 1994 algorithm, the end of the Nth pass whose label
// contains a text (`after`), or the finished render (`after: end`). The
// watcher evaluates them while the render runs; it reads the buffers and
// changes nothing, so a render with expectations draws the same bytes.
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/gl_command_stream.hpp"
#include "framebuffer/script_probe.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "scene/scene.hpp"

namespace mpr {

// Whether a pass label is one the expectation names: it contains `after`,
// and, when given, its innermost draw_window is at `level` and it runs inside
// that window's loop over light `light`. Never for `after: end`.
bool passMatches(const SceneExpectation& e, const std::string& label);

// The expectation in words, for listings and failures:
// `after "draw_all_shadows > shadow volumes", light 0: stencil SHAD_ZERO + 1 = 193 at (4,7)`.
std::string expectationText(const SceneExpectation& e);

struct ExpectationOutcome {
  bool evaluated = false;  // a pass matched (always, for `after: end`)
  int pass = 0;            // where: the pass number as `mpr step` counts them (1 the first @pass)
  std::string passLabel;   // its label ("end": the finished render)
  std::size_t order = 0;   // the evaluation's place in the render (0 the first)
  ProbeOutcome probe;
  std::vector<std::uint8_t> difference;  // probeDifferenceImage when it does not hold
};

class SceneExpectationWatcher {
 public:
  // Watches the passes of `stream` (it takes the stream's onPassEnd); `gl` is
  // the stream's context. The scene must outlive the watcher.
  SceneExpectationWatcher(const Scene& scene, GLCommandStream& stream, const GLContext& gl);
  // After renderScene: closes the last pass and evaluates the `after: end` entries.
  void finish();

  // One per scene.expectations entry, in file order.
  const std::vector<ExpectationOutcome>& outcomes() const { return outcomes_; }
  // The first entry, in the render's order, that was evaluated and did not
  // hold (the earliest wrong buffer); -1 when none.
  int firstFailure() const;
  // The entries no pass matched (file order).
  std::vector<int> unmatched() const;
  int passes() const { return passes_; }
  // How many passes entry i matched (up to its occurrence).
  int matches(std::size_t i) const { return seen_[i]; }

 private:
  void evaluate(std::size_t i, const std::string& label);
  const Scene& scene_;
  GLCommandStream& stream_;
  const GLContext& gl_;
  std::vector<ExpectationOutcome> outcomes_;
  std::vector<int> seen_;  // passes matched so far, per entry
  int passes_ = 0;
  std::size_t evaluations_ = 0;
};

}  // namespace mpr
