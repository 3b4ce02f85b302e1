// The embedded default scene: what `mpr render` draws with no scene file.
#include "scene/scene_loader.hpp"

namespace mpr {

const std::string& defaultSceneText() {
  static const std::string text = R"(# The default scene: a room with a mirror, a glass pane, a cube, a sphere
# and one light.
camera:
  position: [0.0, 1.7, 6.5]
  look_at: [0.0, 1.0, 0.0]
  fov: 45
  near: 0.1
  far: 50
ambient: [0.12, 0.12, 0.14]
lights:
  - position: [1.5, 3.4, 2.5]
    color: [1.0, 0.95, 0.85]
    attenuation: [1.0, 0.02, 0.01]
    radius: 0.15
materials:
  floor:   {diffuse: [0.75, 0.72, 0.66]}
  wall:    {diffuse: [0.62, 0.68, 0.78]}
  red:     {diffuse: [0.85, 0.22, 0.15], specular: [0.4, 0.4, 0.4], shininess: 32}
  blue:    {diffuse: [0.2, 0.35, 0.85], roughness: 0.2, specular: [0.04, 0.04, 0.04]}
  mirror:  {kind: mirror, diffuse: [0.05, 0.05, 0.05], reflectance: 0.9}
  glass:   {kind: refractive, diffuse: [0.7, 0.8, 0.85], ior: 1.5, transmittance: 0.85}
objects:
  - {name: floor, primitive: plane, subdivisions: 8, scale: [8, 1, 8], material: floor}
  - {name: back wall, primitive: quad, translate: [0, 2, -3], scale: [8, 4, 1], material: wall}
  - {name: left wall, primitive: quad, translate: [-4, 2, 1], rotate: [90, 0, 1, 0], scale: [8, 4, 1], material: wall}
  - {name: right wall, primitive: quad, translate: [4, 2, 1], rotate: [-90, 0, 1, 0], scale: [8, 4, 1], material: wall}
  - {name: mirror, primitive: quad, translate: [0, 1.6, -2.98], scale: [2.4, 1.8, 1], material: mirror}
  - {name: glass pane, primitive: quad, translate: [1.6, 0.9, 0.8], rotate: [-30, 0, 1, 0], scale: [1.2, 1.6, 1], material: glass}
  - {name: cube, primitive: box, translate: [-1.0, 0.5, 0.2], rotate: [25, 0, 1, 0], material: red}
  - {name: sphere, primitive: sphere, subdivisions: 48, translate: [0.6, 0.55, -0.8], scale: 0.55, material: blue}
render:
  width: 640
  height: 480
  recursion_depth: 2
  profile: indigo
)";
  return text;
}

}  // namespace mpr
