#pragma once
// The seam between the algorithms and the emulated hardware (DESIGN.md): every
// GL call an algorithm makes goes through this stream, which executes it on
// the GLContext and, on request, records it as a GL script line. Each number
// is executed exactly as its recorded text parses, so `mpr gl` replays a trace
// to the same bytes.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/gl_context.hpp"
#include "pipeline/gl_script.hpp"

namespace mpr {

// One argument: a number (single or double precision, as the C call takes
// it) or a GL enumerant name.
struct GLArg {
  enum class Kind : std::uint8_t { Float, Double, Int, Enum } kind;
  double number = 0.0;
  std::string_view name;
  GLArg(float v) : kind(Kind::Float), number(v) {}
  GLArg(double v) : kind(Kind::Double), number(v) {}
  GLArg(int v) : kind(Kind::Int), number(v) {}
  GLArg(std::string_view enumName) : kind(Kind::Enum), name(enumName) {}
  GLArg(const char* enumName) : kind(Kind::Enum), name(enumName) {}
};

struct PassStatistics {
  std::uint64_t passes = 0, calls = 0, triangles = 0, fragmentsTested = 0, fragmentsWritten = 0;
  double seconds = 0.0;
};

class GLCommandStream {
 public:
  GLCommandStream(GLContext& gl, bool recordTrace);

  void call(GLCall c, std::initializer_list<GLArg> args);
  // Starts a pass: `kind` groups statistics ("ambient", "light"), `label` is the @pass line.
  void pass(const std::string& kind, const std::string& label);
  void finish();  // closes the last pass's timing
  // Called with a pass's label when it ends (the next pass starts, or finish):
  // tests and the stepper look at the buffers there.
  void onPassEnd(std::function<void(const std::string& label)> f) { passEnd_ = std::move(f); }

  // The end-of-pipeline map (GLContext::setWindowMap; the 1994 paper's wished
  // hardware stage, not a GL call). Recorded in the trace as a comment only,
  // so a trace of a render that used it does not replay to the same bytes.
  void windowMap(const std::optional<glm::mat3>& map);
  bool usedWindowMap() const { return usedWindowMap_; }

  const std::string& trace() const { return trace_; }
  std::uint64_t glErrors() const { return glErrors_; }
  std::uint64_t calls() const { return calls_; }
  const std::map<std::string, PassStatistics>& passStatistics() const { return stats_; }
  GLContext& context() { return gl_; }

 private:
  void closePass();
  GLContext& gl_;
  bool record_;
  std::string trace_;
  std::uint64_t calls_ = 0, glErrors_ = 0;
  bool usedWindowMap_ = false;
  std::map<std::string, PassStatistics> stats_;
  std::string currentKind_, currentLabel_;
  std::function<void(const std::string&)> passEnd_;
  std::chrono::steady_clock::time_point passStart_;
  PipelineCounters countersAtPassStart_;
  std::uint64_t callsAtPassStart_ = 0;
};

}  // namespace mpr
