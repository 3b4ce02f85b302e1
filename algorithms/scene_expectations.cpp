#include "algorithms/scene_expectations.hpp"

#include <limits>

namespace mpr {
namespace {

// The label's routine path, split at " > " (the last part is the pass's own
// "what | pseudo-code").
std::vector<std::string> labelParts(const std::string& label) {
  std::vector<std::string> parts;
  for (std::size_t from = 0;;) {
    const std::size_t at = label.find(" > ", from);
    parts.push_back(label.substr(from, at == std::string::npos ? std::string::npos : at - from));
    if (at == std::string::npos) break;
    from = at + 3;
  }
  return parts;
}

bool numberAfter(const std::string& part, const std::string& prefix, int& n) {
  if (part.rfind(prefix, 0) != 0 || part.size() == prefix.size()) return false;
  const std::string digits = part.substr(prefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos) return false;
  n = std::stoi(digits);
  return true;
}

}  // namespace

bool passMatches(const SceneExpectation& e, const std::string& label) {
  if (e.atEnd() || label.find(e.after) == std::string::npos) return false;
  if (e.level < 0 && e.light < 0) return true;
  // The innermost draw_window, and the light loop inside it.
  const std::vector<std::string> parts = labelParts(label);
  int level = -1, light = -1;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    int n = 0;
    if (numberAfter(parts[i], "draw_window level ", n)) {
      level = n;
      light = -1;
    } else if (numberAfter(parts[i], "light ", n)) {
      light = n;
    } else if (parts[i].rfind("draw_ref_objects", 0) == 0) {
      light = -1;
    }
  }
  if (e.level >= 0 && level != e.level) return false;
  if (e.light >= 0 && light != e.light) return false;
  return true;
}

std::string expectationText(const SceneExpectation& e) {
  std::string o = e.atEnd() ? "after end" : "after \"" + e.after + "\"";
  if (e.occurrence > 1) o += ", occurrence " + std::to_string(e.occurrence);
  if (e.level >= 0) o += ", level " + std::to_string(e.level);
  if (e.light >= 0) o += ", light " + std::to_string(e.light);
  return o + ": " + probeText(e.probe);
}

SceneExpectationWatcher::SceneExpectationWatcher(const Scene& scene, GLCommandStream& stream, const GLContext& gl)
    : scene_(scene), stream_(stream), gl_(gl), outcomes_(scene.expectations.size()), seen_(scene.expectations.size(), 0) {
  stream_.onPassEnd([this](const std::string& label) {
    ++passes_;
    for (std::size_t i = 0; i < scene_.expectations.size(); ++i) {
      const SceneExpectation& e = scene_.expectations[i];
      if (outcomes_[i].evaluated || !passMatches(e, label)) continue;
      if (++seen_[i] == e.occurrence) evaluate(i, label);
    }
  });
}

void SceneExpectationWatcher::evaluate(std::size_t i, const std::string& label) {
  const ScriptProbe& p = scene_.expectations[i].probe;
  const Framebuffer& fb = gl_.framebuffer();
  ExpectationOutcome& o = outcomes_[i];
  o.evaluated = true;
  o.pass = passes_;
  o.passLabel = label;
  o.order = evaluations_++;
  o.probe = evaluateProbe(p, fb);
  if (!o.probe.passed) o.difference = probeDifferenceImage(p, fb);
}

void SceneExpectationWatcher::finish() {
  stream_.endPasses();
  stream_.onPassEnd({});
  for (std::size_t i = 0; i < scene_.expectations.size(); ++i)
    if (scene_.expectations[i].atEnd()) evaluate(i, "end");
}

int SceneExpectationWatcher::firstFailure() const {
  int first = -1;
  for (std::size_t i = 0; i < outcomes_.size(); ++i) {
    const ExpectationOutcome& o = outcomes_[i];
    if (!o.evaluated || o.probe.passed) continue;
    if (first < 0 || o.order < outcomes_[static_cast<std::size_t>(first)].order) first = static_cast<int>(i);
  }
  return first;
}

std::vector<int> SceneExpectationWatcher::unmatched() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < outcomes_.size(); ++i)
    if (!outcomes_[i].evaluated) out.push_back(static_cast<int>(i));
  return out;
}

}  // namespace mpr
