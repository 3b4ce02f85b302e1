#include "algorithms/gl_command_stream.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <stdexcept>

#include "pipeline/gl_enums.hpp"
#include "pipeline/gl_script_runner.hpp"

namespace mpr {
namespace {

// Shortest text that reads back as the same value of the call's own type.
std::string numberText(const GLArg& a) {
  char buf[64];
  std::to_chars_result r;
  if (a.kind == GLArg::Kind::Float) r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(a.number));
  else if (a.kind == GLArg::Kind::Int) r = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(a.number));
  else r = std::to_chars(buf, buf + sizeof buf, a.number);
  return std::string(buf, r.ptr);
}

}  // namespace

GLCommandStream::GLCommandStream(GLContext& gl, bool recordTrace) : gl_(gl), record_(recordTrace) {
  passStart_ = std::chrono::steady_clock::now();
  if (record_)
    trace_ = "@framebuffer " + std::to_string(gl.framebuffer().width()) + " " +
             std::to_string(gl.framebuffer().height()) + "\n@profile " + gl.framebuffer().profile().name + "\n";
}

void GLCommandStream::call(GLCall c, std::initializer_list<GLArg> args) {
  ScriptCommand cmd;
  cmd.call = c;
  std::string line(glCallName(c));
  for (const GLArg& a : args) {
    ScriptArg s;
    if (a.kind == GLArg::Kind::Enum) {
      // A name, or names joined by '|' for a bitfield.
      std::uint32_t bits = 0;
      for (std::size_t start = 0; start <= a.name.size();) {
        const std::size_t bar = std::min(a.name.find('|', start), a.name.size());
        const auto v = glEnumValue(a.name.substr(start, bar - start));
        if (!v) throw std::logic_error("unknown GL enumerant " + std::string(a.name));
        bits |= *v;
        start = bar + 1;
      }
      s.text = std::string(a.name);
      s.bits = bits;
      s.number = bits;
    } else {
      s.text = numberText(a);
      s.number = std::strtod(s.text.c_str(), nullptr);  // what a replay will read
      s.bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(s.number));
    }
    line += ' ';
    line += s.text;
    cmd.args.push_back(std::move(s));
  }
  executeCall(gl_, cmd);
  ++calls_;
  if (!gl_.insideBeginEnd() && gl_.getError() != 0) ++glErrors_;
  if (record_) {
    trace_ += line;
    trace_ += '\n';
  }
}

void GLCommandStream::windowMap(const std::optional<glm::mat3>& map) {
  if (map == gl_.windowMap()) return;
  gl_.setWindowMap(map);
  if (map) usedWindowMap_ = true;
  if (!record_) return;
  trace_ += "# MPR end-of-pipeline map (not a GL call; a replay lacks it):";
  if (!map) trace_ += " off";
  for (int k = 0; map && k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      trace_ += ' ';
      trace_ += numberText(GLArg((*map)[k][i]));
    }
  trace_ += '\n';
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
  if (record_) trace_ += "@pass " + label + "\n";
}

void GLCommandStream::finish() {
  closePass();
  if (passEnd_ && !currentKind_.empty()) passEnd_(currentLabel_);
  currentKind_.clear();
}

}  // namespace mpr
