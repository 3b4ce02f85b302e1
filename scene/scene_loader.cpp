// Scene files to the scene model: the YAML text parsed (one document, the
// --set overrides placed in it), then read section by section
// (scene/scene_section_readers.hpp), each value checked as it is read.
#include "scene/scene_loader.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "scene/scene_format.hpp"
#include "scene/scene_node_reader.hpp"
#include "scene/scene_overrides.hpp"
#include "scene/scene_section_readers.hpp"
#include "util/input_file.hpp"

namespace mpr {
namespace {

// The sections in the order they depend on one another.
Scene readScene(const SceneNodeReader& in, YAML::Node doc, bool confine) {
  Scene s;
  s.file = in.file();
  if (doc.IsNull()) doc = YAML::Node(YAML::NodeType::Map);
  in.checkKeys(doc, scene_format::kTopKeys, "the scene");
  if (const YAML::Node r = doc["render"]) readRenderSettings(in, r, s.render);
  if (const YAML::Node c = doc["camera"]) s.origin = readCamera(in, c, s.camera);
  if (const YAML::Node a = doc["ambient"]) s.ambient = in.rgb(a, "ambient");
  if (const YAML::Node ls = doc["lights"]) readLights(in, ls, s.origin, s.lights);
  std::map<std::string, int> materialIndex;
  s.materials.push_back(SceneMaterial{"default"});
  if (const YAML::Node ms = doc["materials"]) materialIndex = readMaterials(in, ms, s.materials);
  if (const YAML::Node os = doc["objects"]) readObjects(in, os, materialIndex, confine, s);
  checkRenderLimits(in, doc, s);
  checkKeysCount(in, doc, s);
  if (const YAML::Node e = doc["expect"]) readExpectations(in, e, s);
  return s;
}

// Where a text's second document starts (its "---"), if it has one. The
// parser is asked for two documents at most: yaml-cpp's LoadAll, which asks
// until none is left, loops for ever on some malformed text (a 524-byte
// scene found by fuzz/scene_fuzzer), handing on an empty document each time.
std::optional<YAML::Mark> secondDocumentStart(const std::string& text) {
  struct Starts : YAML::EventHandler {
    std::vector<YAML::Mark> marks;
    void OnDocumentStart(const YAML::Mark& m) override { marks.push_back(m); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
  } starts;
  std::istringstream in(text);
  YAML::Parser parser(in);
  for (int i = 0; i < 2 && parser.HandleNextDocument(starts); ++i) {
  }
  if (starts.marks.size() > 1) return starts.marks[1];
  return std::nullopt;
}

}  // namespace

Scene loadSceneText(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                    bool confine) {
  YAML::Node doc;
  try {
    // YAML::Load reads up to a second document's "---" and drops the rest
    // of the file without a word: a second document is refused.
    if (const std::optional<YAML::Mark> m = secondDocumentStart(text)) {
      // A real second document follows a "---" or a "..." that ended the
      // first; anything else is text yaml-cpp could not fit into the first.
      const std::size_t pos = static_cast<std::size_t>(std::max(m->pos, 0));
      const std::size_t before = text.find_last_not_of(" \t\r\n", pos == 0 ? 0 : pos - 1);
      const bool marked = text.compare(pos, 3, "---") == 0 ||
                          (pos > 0 && before != std::string::npos && before >= 2 && text.compare(before - 2, 3, "...") == 0);
      throw SceneError(file, m->line + 1, m->column + 1,
                       marked ? "a second YAML document starts here; a scene file holds one (remove this '---' and "
                                "what follows, or merge it into the first)"
                              : "YAML syntax: this does not continue the document above it (a scene file holds one "
                                "YAML document)");
    }
    // (An empty text has no document: a null node of its own, which a --set
    // path can make a mapping of.)
    doc = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, "YAML syntax: " + e.msg);
  }
  std::vector<SceneOverride> applied;
  for (const std::string& kv : overrides) applied.push_back(applyOverride(doc, kv));
  try {
    const SceneNodeReader in(file, applied);
    Scene scene = readScene(in, doc, confine);
    for (const std::string& w : in.warnings()) std::cerr << w << "\n";
    return scene;
  } catch (const YAML::Exception& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides, bool confine) {
  std::string text;
  try {
    text = readInputFile(path, kMaxSceneBytes, "the scene file");
  } catch (const std::runtime_error& e) {
    throw SceneError(path, 0, 0, e.what());
  }
  return loadSceneText(text, path, overrides, confine);
}

}  // namespace mpr
