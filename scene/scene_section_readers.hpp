#pragma once
// The readers of a scene file's sections, one file each (render_settings_,
// camera_, light_, material_, object_ and expectation_reader.cpp, and
// keys_count.cpp for what depends on several sections), called
// in this order by loadSceneText (scene/scene_loader.hpp): a section may
// depend on those read before it (objects on materials, expectations on the
// render settings and lights). Each reads through a SceneNodeReader, which
// places its errors, and adds what it read to the scene.
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_node_reader.hpp"

namespace mpr {

// render: image size, recursion, effects, hardware profile.
void readRenderSettings(const SceneNodeReader& in, const YAML::Node& n, RenderSettings& r);
// camera: the viewer. Gives the scene's origin (scene/camera_origin.hpp):
// the positions read from here on are made relative to it.
DVec3 readCamera(const SceneNodeReader& in, const YAML::Node& n, Camera& c);
// lights: point lights (at most kMaxSceneLights), relative to `origin`.
void readLights(const SceneNodeReader& in, const YAML::Node& list, DVec3 origin, std::vector<PointLight>& lights);
// materials: named materials, appended to `materials`; gives each name's index there.
std::map<std::string, int> readMaterials(const SceneNodeReader& in, const YAML::Node& map,
                                         std::vector<SceneMaterial>& materials);
// objects: primitives and meshes (at most kMaxSceneObjects, kMaxSceneTriangles
// in all), placed (relative to s.origin) and given their materials
// (`materials`: readMaterials' index).
// `confine`: meshes only from inside the scene's folder (mpr render --confine).
void readObjects(const SceneNodeReader& in, const YAML::Node& list, const std::map<std::string, int>& materials,
                 bool confine, Scene& s);
// What the render settings ask of the scene read so far: the triangles
// render.tessellation makes, the stencil levels the recursion needs,
// darkness_levels' stencil counts and accumulation buffer.
void checkRenderLimits(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s);
// pbrt's rule for the keys whose use depends on the rest of the scene
// (scene/keys_count.cpp): a render key, a light's radius, the camera's lens
// or a material that would change nothing is refused at its place in the
// file, or, where mpr reference still uses it, warned about once.
void checkKeysCount(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s);
// expect: probes of the buffers at named points of the render.
void readExpectations(const SceneNodeReader& in, const YAML::Node& list, Scene& s);

}  // namespace mpr
