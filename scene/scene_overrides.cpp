#include "scene/scene_overrides.hpp"

#include <cstddef>

#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

// Whether `at` is `root` or lies inside it (a key or a value at any depth):
// an error there is the --set's that gave `root`, not the file's.
bool within(const YAML::Node& at, const YAML::Node& root) {
  if (at.is(root)) return true;
  if (root.IsSequence()) {
    for (const YAML::Node& c : root)
      if (within(at, c)) return true;
  } else if (root.IsMap()) {
    for (auto it = root.begin(); it != root.end(); ++it)
      if (within(at, it->first) || within(at, it->second)) return true;
  }
  return false;
}

}  // namespace

bool SceneOverride::gave(const YAML::Node& at) const { return within(at, node); }

bool SceneOverride::made(const YAML::Node& at) const {
  for (const YAML::Node& c : created)
    if (at.is(c)) return true;
  return false;
}

bool SceneOverride::inside(const YAML::Node& root) const { return root && within(node, root); }

SceneOverride applyOverride(YAML::Node& doc, const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError("--set", 1, 1, "'" + kv + "' must be key.path=value");
  const std::string path = kv.substr(0, eq), value = kv.substr(eq + 1);
  std::vector<std::string> keys;
  std::vector<std::size_t> columns;  // each key's, 1-based in kv
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    keys.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    columns.push_back(start + 1);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  const std::string where = "--set " + kv;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i].empty())
      throw SceneError(where, 1, static_cast<int>(columns[i]), "'" + path + "' has an empty key; keys are joined by single dots");
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw SceneError("--set", 1, static_cast<int>(eq) + 2, "'" + value + "' is not a YAML value: " + e.msg);
  }
  SceneOverride o{kv, {}, {}};
  // yaml-cpp nodes are handles (assigning one to another rebinds the
  // first's node): walk down by copying handles, then assign. A list is
  // entered by its index (objects.0.scale): yaml-cpp's operator[] with a
  // text key turned the list into a mapping {"0": ...}, which the loader
  // then refused for not being a list, against the scene file.
  std::vector<YAML::Node> chain{doc};
  std::string name;  // the path so far
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    const bool last = i + 1 == keys.size();
    const int column = static_cast<int>(columns[i]);
    YAML::Node at = chain.back();
    if (at.IsSequence()) {
      const bool digits = key.size() <= 9 && key.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t index = digits ? std::stoul(key) : 0;
      if (!digits || index >= at.size())
        throw SceneError(where, 1, column,
                         name + " is a list of " + std::to_string(at.size()) + (at.size() == 1 ? " entry" : " entries") +
                             (at.size() == 0 ? "" : ": give an index from 0 to " + std::to_string(at.size() - 1)) +
                             ", not '" + key + "'");
      if (last) {
        at[index] = parsed;
        o.node.reset(at[index]);
        return o;
      }
      chain.push_back(at[index]);
    } else if (at.IsScalar()) {
      throw SceneError(where, 1, column, name + " is a value ('" + at.Scalar() + "'), not a mapping with a key '" + key + "'");
    } else {  // a mapping, or null (an empty document): operator[] makes it a mapping
      if (last) {
        at[key] = parsed;
        o.node.reset(at[key]);
        return o;
      }
      const YAML::Node next = at[key];
      if (!next.IsDefined() || next.IsNull()) {
        at[key] = YAML::Node(YAML::NodeType::Map);
        o.created.push_back(at[key]);
      }
      chain.push_back(at[key]);
    }
    name += (name.empty() ? "" : ".") + key;
  }
  return o;
}

}  // namespace mpr
