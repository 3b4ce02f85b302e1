#include "scene/scene_node_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

#include "scene/scene_loader.hpp"
#include "util/spelling.hpp"

namespace mpr {

void SceneNodeReader::fail(const YAML::Node& at, const std::string& message) const {
  // A value that came from --set has no place in the file: name the option.
  // The last --set first: a later one may have replaced what an earlier gave.
  for (auto o = overrides_.rbegin(); o != overrides_.rend(); ++o)
    if (o->gave(at) || o->made(at)) throw SceneError("--set " + o->text, 1, 1, message);
  const YAML::Mark m = at.Mark();
  if (m.is_null() && !overrides_.empty()) {  // a key --set created
    std::string all;
    for (const SceneOverride& o : overrides_) all += (all.empty() ? "" : " --set ") + o.text;
    throw SceneError("--set " + all, 1, 1, message);
  }
  throw SceneError(file_, m.line + 1, m.column + 1, message);
}

bool SceneNodeReader::givenBySet(const YAML::Node& at) const {
  return std::any_of(overrides_.begin(), overrides_.end(), [&](const SceneOverride& o) { return o.gave(at); });
}

bool SceneNodeReader::setInside(const YAML::Node& root) const {
  return std::any_of(overrides_.begin(), overrides_.end(), [&](const SceneOverride& o) { return o.inside(root); });
}

void SceneNodeReader::warn(const YAML::Node& at, const std::string& message) const {
  try {
    fail(at, "warning: " + message);
  } catch (const SceneError& e) {
    warnings_.push_back(e.what());
  }
}

// YAML forbids a key twice in one mapping; yaml-cpp keeps both and reads
// the first, so `scale: 1` then `scale: 0` would silently drop the second.
void SceneNodeReader::checkUniqueKeys(const YAML::Node& map, const std::string& where) const {
  std::map<std::string, YAML::Mark> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (!it->first.IsScalar()) fail(it->first, "a key in " + where + " must be a plain name");
    const auto [at, fresh] = seen.emplace(it->first.Scalar(), it->first.Mark());
    if (!fresh)
      fail(it->first, "key '" + it->first.Scalar() + "' given twice in " + where + " (first at line " +
                          std::to_string(at->second.line + 1) + ", column " + std::to_string(at->second.column + 1) +
                          "); give it once");
  }
}

void SceneNodeReader::checkKeys(const YAML::Node& map, const std::vector<scene_format::KeySpec>& keys, const std::string& where) const {
  if (!map.IsMap()) fail(map, where + " must be a mapping");
  checkUniqueKeys(map, where);
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (std::any_of(keys.begin(), keys.end(), [&](const scene_format::KeySpec& s) { return s.key == k; })) continue;
    std::vector<std::string_view> names;
    for (const scene_format::KeySpec& s : keys) names.push_back(s.key);
    const std::string best = closestMatch(k, names, 3);
    std::string known;
    for (const scene_format::KeySpec& s : keys) known += (known.empty() ? "" : ", ") + std::string(s.key);
    fail(it->first, "unknown key '" + k + "' in " + where +
                        (best.empty() ? " (known: " + known + ")" : "; did you mean '" + best + "'?"));
  }
}

// A list whose entries multiply the render's work, bounded before any is read.
void SceneNodeReader::checkCount(const YAML::Node& list, const std::string& key, std::size_t max) const {
  if (list.size() > max)
    fail(list, key + " lists " + std::to_string(list.size()) + " entries, more than the " + std::to_string(max) +
                   " a scene may hold (each multiplies the render's passes; YAML aliases repeat an entry at no cost in "
                   "the file)");
}

// A number, a boolean: a plain scalar only. yaml-cpp hands a quoted
// scalar ('45', "true") over with the same text as a plain one, so without
// this a string stood in for a number wherever one was read; its tag ("!"
// for a quoted scalar, "?" for a plain one) tells them apart.
void SceneNodeReader::checkPlain(const YAML::Node& n, const std::string& what, const std::string& kind) const {
  const std::string& tag = n.Tag();
  if (tag == "?" || tag.empty()) return;
  if (tag == "!")
    fail(n, what + " must be " + kind + ", not the quoted string '" + n.Scalar() + "' (write it without quotes)");
  if (kind == "a number" && (tag == "tag:yaml.org,2002:float" || tag == "tag:yaml.org,2002:int")) return;
  if (kind == "true or false" && tag == "tag:yaml.org,2002:bool") return;
  fail(n, what + " must be " + kind + ", not a value tagged '" + tag + "'");
}

double SceneNodeReader::number(const YAML::Node& n, const std::string& what) const {
  if (!n.IsScalar()) fail(n, what + " must be a number");
  checkPlain(n, what, "a number");
  const std::string s = n.Scalar();
  // YAML's own spellings of the non-finite values.
  static const char* const nonFinite[] = {".nan", ".NaN", ".NAN", ".inf", ".Inf", ".INF", "+.inf", "+.Inf",
                                          "+.INF", "-.inf", "-.Inf", "-.INF"};
  for (const char* nf : nonFinite)
    if (s == nf) fail(n, what + " must be finite, not '" + s + "'");
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) fail(n, what + " must be a number, not '" + s + "'");
  if (!std::isfinite(v)) fail(n, what + " must be finite, not '" + s + "'");
  // Every scene number is used as a float: 1e39 is finite as a double and
  // infinite as a float, so the check is on the range it will be used in.
  if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
    fail(n, what + " must be within a float's range (magnitude at most 3.4e38), not '" + s + "'");
  return v;
}

double SceneNodeReader::number(const YAML::Node& n, const std::string& what, double lo, double hi, bool openLo) const {
  const double v = number(n, what);
  if (v < lo || v > hi || (openLo && v == lo)) {
    std::ostringstream r;
    r << what << " must be in " << (openLo ? "(" : "[") << lo << ", " << hi << "], not " << n.Scalar();
    fail(n, r.str());
  }
  return v;
}

int SceneNodeReader::integer(const YAML::Node& n, const std::string& what, long lo, long hi) const {
  const double v = number(n, what);
  if (v != std::floor(v)) fail(n, what + " must be an integer, not " + n.Scalar());
  if (v < lo || v > hi)
    fail(n, what + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + n.Scalar());
  return static_cast<int>(v);
}

bool SceneNodeReader::boolean(const YAML::Node& n, const std::string& what) const {
  if (!n.IsScalar()) fail(n, what + " must be true or false");
  checkPlain(n, what, "true or false");
  const std::string s = n.Scalar();
  if (s == "true" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "no" || s == "off") return false;
  fail(n, what + " must be true or false, not '" + s + "'");
}

std::string SceneNodeReader::string(const YAML::Node& n, const std::string& what) const {
  if (!n.IsScalar()) fail(n, what + " must be a string");
  return n.Scalar();
}

Vec3 SceneNodeReader::vec3(const YAML::Node& n, const std::string& what) const { return Vec3(dvec3(n, what)); }

DVec3 SceneNodeReader::dvec3(const YAML::Node& n, const std::string& what) const {
  if (!n.IsSequence() || n.size() != 3) fail(n, what + " must be a list of 3 numbers, like [0, 1, 0]");
  return DVec3(number(n[0], what + "[0]"), number(n[1], what + "[1]"), number(n[2], what + "[2]"));
}

Vec3 SceneNodeReader::rgb(const YAML::Node& n, const std::string& what) const {
  const Vec3 c = vec3(n, what);
  for (int i = 0; i < 3; ++i)
    if (c[i] < 0.0f) fail(n, what + " must not be negative");
  return c;
}

}  // namespace mpr
