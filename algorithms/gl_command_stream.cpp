#include "algorithms/gl_command_stream.hpp"

namespace mpr {

GLCommandStream::GLCommandStream(GLContext& gl, bool recordTrace) : gl_(gl), emulator_(gl) {
  passStart_ = std::chrono::steady_clock::now();
  if (recordTrace)
    writer_ = std::make_unique<GLTraceWriter>(gl.framebuffer().width(), gl.framebuffer().height(),
                                              gl.framebuffer().profile().name);
}

const std::string& GLCommandStream::trace() const {
  static const std::string none;
  return writer_ ? writer_->text() : none;
}

void GLCommandStream::windowMap(const std::optional<glm::mat3>& map) {
  if (map == gl_.windowMap()) return;
  emulator_.windowMap(map);
  if (writer_) writer_->windowMap(map);
}

void GLCommandStream::beginFragmentCount() {
  emulator_.beginFragmentCount();
  if (writer_) writer_->beginFragmentCount();
}

std::uint64_t GLCommandStream::endFragmentCount() {
  if (writer_) writer_->endFragmentCount();
  return emulator_.endFragmentCount();
}

void GLCommandStream::closePass() {
  if (currentKind_.empty()) return;
  PassStatistics& s = stats_[currentKind_];
  const PipelineCounters& now = gl_.counters();
  s.calls += calls_ - callsAtPassStart_;
  s.triangles += now.triangles - countersAtPassStart_.triangles;
  s.fragmentsTested += now.fragmentsTested - countersAtPassStart_.fragmentsTested;
  s.fragmentsWritten += now.fragmentsWritten - countersAtPassStart_.fragmentsWritten;
  s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - passStart_).count();
}

void GLCommandStream::pass(const std::string& kind, const std::string& label) {
  closePass();
  if (passEnd_ && !currentKind_.empty()) passEnd_(currentLabel_);
  currentKind_ = kind;
  currentLabel_ = label;
  ++stats_[kind].passes;
  passStart_ = std::chrono::steady_clock::now();
  countersAtPassStart_ = gl_.counters();
  callsAtPassStart_ = calls_;
  if (writer_) writer_->pass(label);
}

void GLCommandStream::endPasses() {
  closePass();
  if (passEnd_ && !currentKind_.empty()) passEnd_(currentLabel_);
  currentKind_.clear();
}

}  // namespace mpr
