#pragma once
// The seam between the algorithms and the emulated hardware (DESIGN.md): every
// GL call an algorithm makes is a typed GLApi call on this stream, a tee that
// executes it on the emulator and, when a trace is asked for, also writes it
// as a GL script line (GLTraceWriter). The render never goes through text;
// the trace's numbers are the shortest that read back to the same values, so
// `mpr gl` replays a trace to the same bytes.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "pipeline/gl/gl_api.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "pipeline/gl/gl_emulator.hpp"
#include "script/gl_trace_writer.hpp"

namespace mpr {

struct PassStatistics {
  std::uint64_t passes = 0, calls = 0, triangles = 0, fragmentsTested = 0, fragmentsWritten = 0;
  double seconds = 0.0;
};

class GLCommandStream final : public GLApi {
 public:
  GLCommandStream(GLContext& gl, bool recordTrace);

#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) \
  void method params override {                                   \
    emulator_.method args;                                        \
    if (writer_) writer_->method args;                            \
    afterCall();                                                  \
  }
#include "pipeline/gl/gl_calls.def"

  // Starts a pass: `kind` groups statistics ("ambient", "light"), `label` is the @pass line.
  void pass(const std::string& kind, const std::string& label);
  void pass(std::string_view label) override { pass("other", std::string(label)); }
  void endPasses();  // closes the last pass's timing (glFinish is finish())
  // Called with a pass's label when it ends (the next pass starts, or finish):
  // tests and the stepper look at the buffers there.
  void onPassEnd(std::function<void(const std::string& label)> f) { passEnd_ = std::move(f); }

  // The end-of-pipeline map (@window_map); written only when it changes.
  void windowMap(const std::optional<glm::mat3>& map) override;
  // The fragment counter (@count_fragments): fragments written in between.
  void beginFragmentCount() override;
  std::uint64_t endFragmentCount() override;

  const std::string& trace() const;
  std::uint64_t glErrors() const { return glErrors_; }
  std::uint64_t calls() const { return calls_; }
  // The pipeline's own counters over the whole render (for --stats).
  const PipelineCounters& counters() const { return gl_.counters(); }
  const std::map<std::string, PassStatistics>& passStatistics() const { return stats_; }

 private:
  void afterCall() {
    ++calls_;
    if (!gl_.insideBeginEnd() && gl_.getError() != 0) ++glErrors_;
  }
  void closePass();
  GLContext& gl_;
  GLEmulator emulator_;
  std::unique_ptr<GLTraceWriter> writer_;
  std::uint64_t calls_ = 0, glErrors_ = 0;
  std::map<std::string, PassStatistics> stats_;
  std::string currentKind_, currentLabel_;
  std::function<void(const std::string&)> passEnd_;
  std::chrono::steady_clock::time_point passStart_;
  PipelineCounters countersAtPassStart_;
  std::uint64_t callsAtPassStart_ = 0;
};

}  // namespace mpr
