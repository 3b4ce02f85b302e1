// The scene loader's anchors and aliases (issue 48: a 3 MB file of a
// million aliases of one light rendered for minutes). The input is a small
// program that writes a scene: anchors on lights, objects, materials,
// expectations, vectors, numbers and mappings, aliases of them repeated up to
// 65 535 times each, merge keys (<<), aliases used as keys, aliases of
// anchors not yet defined or defined twice. Every scene it writes must load
// or be refused with a SceneError, and a loaded one must hold the limits
// (scene/scene_loader.hpp): no more lights, objects, expectations or
// triangles than a scene may hold; and it must plan.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "algorithms/render_plan.hpp"
#include "scene/scene_loader.hpp"

namespace {

// The entries a list may take, each with an anchor or as an alias. Meshes
// stay small: a scene of 24 Mi triangles is allowed and takes minutes to
// build under the sanitizers, which is the triangle budget's business (the
// hostile corpus), not this harness's.
const char* const kLight[] = {"{position: [0, 2, 0]}", "{position: [1, 1, 1], color: [1, 1, 1], radius: 0.1}",
                              "{position: [0, 1e30, 0]}", "{position: [0, 2]}"};
const char* const kObject[] = {"{primitive: box}", "{primitive: quad, material: m}", "{primitive: sphere, subdivisions: 4}",
                               "{primitive: plane}", "{primitive: box, translate: [0, 0, -3]}"};
const char* const kExpect[] = {"{after: end, stencil: [0, 0], value: 0}", "{after: end, color: [1, 1], value: [0, 0, 0]}",
                               "{after: ambient, stencil: [2, 2], value: ZERO}"};

struct Reader {
  const std::uint8_t* p;
  std::size_t n;
  std::uint8_t byte() { return n ? (--n, *p++) : 0; }
  unsigned count() {
    const unsigned high = byte();
    return high << 8 | byte();
  }
};

template <std::size_t N>
const char* pick(const char* const (&table)[N], std::uint8_t b) {
  return table[b % N];
}

// A list of `key`: entries with anchors &k0.. and aliases of them, repeated.
void list(std::string& yaml, Reader& r, const char* key, const char* prefix, const auto& table) {
  yaml += key;
  yaml += ":\n";
  const int entries = 1 + r.byte() % 6;
  int anchors = 0;
  for (int i = 0; i < entries; ++i) {
    const std::uint8_t op = r.byte();
    if (op % 3 == 0 || anchors == 0) {
      yaml += "  - &" + std::string(prefix) + std::to_string(anchors++) + " " + pick(table, r.byte()) + "\n";
    } else {
      // An alias repeated; sometimes of an anchor not (yet) defined.
      const int target = r.byte() % (anchors + 1);
      const unsigned repeat = r.count();
      for (unsigned k = 0; k <= repeat; ++k) yaml += "  - *" + std::string(prefix) + std::to_string(target) + "\n";
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader r{data, size};
  std::string yaml;
  const std::uint8_t shape = r.byte();
  // Shared anchors used inside entries: a vector, a number, a mapping merged.
  if (shape & 1) yaml += "ambient: &v [0.1, 0.1, 0.1]\n";
  if (shape & 2) yaml += "camera: &cam {position: [0, 1, 5], look_at: [0, 0, 0], fov: &f 45}\n";
  if (shape & 4) yaml += "render: &r {width: 16, height: 12}\n";
  if (shape & 8) yaml += "materials:\n  m: &mat {kind: mirror}\n  n: *mat\n";
  if (shape & 16) list(yaml, r, "lights", "l", kLight);
  if (shape & 32) list(yaml, r, "objects", "o", kObject);
  if (shape & 64) list(yaml, r, "expect", "e", kExpect);
  if (shape & 128) {
    // Aliases where scalars, keys and merges go.
    const std::uint8_t how = r.byte();
    if (how & 1) yaml += "extra: *v\n";
    if (how & 2) yaml += "? *f\n: 1\n";
    if (how & 4) yaml += "render: {<<: *r, width: 8}\n";
    if (how & 8) yaml += "camera: *cam\n";
    if (how & 16) yaml += "lights: [*l0, *l0, *v]\n";
  }
  yaml.append(reinterpret_cast<const char*>(r.p), r.n);  // the rest as text
  try {
    const mpr::Scene scene = mpr::loadSceneText(yaml, "fuzz/corpus.yaml");
    if (scene.lights.size() > mpr::kMaxSceneLights || scene.objects.size() > mpr::kMaxSceneObjects ||
        scene.expectations.size() > mpr::kMaxSceneExpectations || scene.triangleCount() > mpr::kMaxSceneTriangles)
      std::abort();  // a limit the loader promised
    if (scene.triangleCount() > 200000) return 0;  // keeps one input fast
    (void)mpr::describePlan(mpr::planRender(scene, true), scene);
  } catch (const mpr::SceneError&) {
  }
  return 0;
}
