#pragma once
// The scene model: what a scene file describes, already validated and with
// every mesh in world space. The renderer reads it; it knows nothing of YAML.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "framebuffer/script_probe.hpp"
#include "util/vecmath.hpp"

namespace mpr {

struct Camera {
  Vec3 position{0.0f, 1.6f, 6.0f};
  Vec3 lookAt{0.0f, 1.0f, 0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float fovY = 45.0f;  // degrees, vertical
  float near = 0.1f;
  float far = 100.0f;
  // Depth of field by accumulation (Haeberli and Akeley 1990): the lens
  // radius (0: a pinhole) and the distance in focus (0: that of look_at).
  float aperture = 0.0f;
  float focalDistance = 0.0f;
};

struct PointLight {
  Vec3 position{0.0f, 3.0f, 0.0f};
  Vec3 color{1.0f, 1.0f, 1.0f};
  Vec3 attenuation{1.0f, 0.0f, 0.0f};  // constant, linear, quadratic
  float radius = 0.0f;                 // area light radius, for soft shadows
};

// The specular kinds the multi-pass effects use (1994 and 1997 papers).
enum class MaterialKind : std::uint8_t { Diffuse, Mirror, Refractive, Translucent, Frosted };

struct SceneMaterial {
  std::string name;
  MaterialKind kind = MaterialKind::Diffuse;
  Vec3 diffuse{0.8f, 0.8f, 0.8f};
  Vec3 specular{0.0f, 0.0f, 0.0f};
  Vec3 emission{0.0f, 0.0f, 0.0f};
  float shininess = 0.0f;       // Phong exponent (from `roughness` by the 1997 paper's eq. 6)
  // Ward's isotropic Gaussian as given (1997 eqs. 3, 5): alpha (0 = none
  // given) and rho_s, the specular before eq. (6) scaled it. The pipeline
  // uses the fitted Phong terms above; the reference's physical model these.
  float roughness = 0.0f;
  Vec3 wardSpecular{0.0f, 0.0f, 0.0f};
  float reflectance = 1.0f;     // mirror
  float ior = 1.5f;             // refractive, translucent, frosted
  float transmittance = 0.9f;   // refractive, translucent, frosted
  float fogDistance = 1.0f;     // translucent: distance of full fog
  float thickness = 0.0f;       // refracting: a slab of this thickness (in-out refraction, 1997 §2); 0: 1994's change of medium
  float shear = 0.05f;          // frosted: stochastic shear amount
  int samples = 8;              // frosted: images accumulated
  bool specularKind() const { return kind != MaterialKind::Diffuse; }
};

// Triangles for drawing, polygons (as given) for the planar-face checks the
// specular effects need.
struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;                           // per position
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::vector<std::uint32_t>> faces;       // the polygons the triangles came from
};

struct SceneObject {
  std::string name;
  Mesh mesh;          // world space
  int material = 0;   // index into Scene::materials
  bool castsShadows = true;  // a shadow volume per light (quads and planes default to false)
  int line = 0;       // where the object is defined, for messages
  std::string meshFile = {};  // the mesh file it was read from (empty for a primitive): an input no output may replace
};

// Where a refracted view's image map M3 (1994 eqs. 1-3) is applied. The
// paper's SGI way is the 4x4 of (A5) on the projection with Z zeroed, which
// "precludes the use of the Z-buffer"; the placement it wished for is a 3x3
// at the end of the pipeline, which keeps depth (an emulated stage, not GL);
// MPR's default is the 4x4 with Z kept, GL-expressible and depth-ordered.
enum class RefractionMap { ProjectionKeptZ, ProjectionZeroedZ, EndOfPipeline };

// How a light with a radius casts soft shadows (render.soft_shadow_method):
// Images, 1994's first method (one whole shadowed render per light sample,
// accumulated); DarknessLevels, its second (every sample's shadow volume
// counted in one stencil, the light added once per darkness level with the
// stencil stepped down between levels, the levels accumulated); Pivot,
// 1997 §4.4 (images, but the shadow volumes built once from the light's
// centre and only their far ends moved per sample, Fig. 7).
enum class SoftShadowMethod { Images, DarknessLevels, Pivot };

// render.tessellation: auto (scene/tessellation.hpp, tessellateLitObjects).
inline constexpr float kAutoTessellation = -1.0f;

struct RenderSettings {
  int width = 640, height = 480;
  int recursionDepth = 2;        // mirror/refraction levels
  int shadowRecursionDepth = 1;
  // Specular faces a light's path may pass (1997 §4.2-4.3: virtual lights of
  // virtual lights); 0: shadow_recursion_depth, at least 1
  // (algorithms/light_path.hpp, lightBounces).
  int lightBounces = 0;
  int softShadowSamples = 1;   // light samples accumulated (1994's first method: shadowed images)
  SoftShadowMethod softShadowMethod = SoftShadowMethod::Images;
  int antialiasSamples = 1;    // jittered images accumulated (and lens samples with an aperture)
  bool shadows = true, reflections = true, refractions = true, translucency = true, frosted = true;
  std::string profile = "indigo";
  RefractionMap refractionMap = RefractionMap::ProjectionKeptZ;
  // The longest edge of a lit triangle the pipeline draws (world units): the
  // planner splits larger ones for GL's per-vertex lighting (0: as modelled;
  // kAutoTessellation, the default: relative to each object's distance to
  // the nearest light, scene/tessellation.hpp).
  float tessellation = kAutoTessellation;
};

// One entry of the scene's `expect:` list (docs/scene-format.md,
// "Expectations"): a probe, as a GL script's @expect, read at the end of the
// `occurrence`-th pass whose label contains `after` (and, when given, runs
// at recursion `level` inside the loop over light `light`), or at the end
// of the render (`after: end`). algorithms/scene_expectations evaluates it.
struct SceneExpectation {
  int line = 0;                    // the entry's line in the scene file
  int afterLine = 0, afterColumn = 0;  // where `after` is written
  std::string after;
  int occurrence = 1;
  int level = -1, light = -1;      // -1: any
  ScriptProbe probe;               // stencil levels already resolved (probe.expectedName keeps the name)
  bool atEnd() const { return after == "end"; }
};

struct Scene {
  std::string file;
  // Where the model's zero lies in the file's world (scene/camera_origin.hpp):
  // every position above is relative to it, so that the float pipeline sees
  // small numbers in a scene far from the world's origin. (0, 0, 0) unless
  // the loader or the renderer moved it to the camera.
  DVec3 origin{0.0};
  Camera camera;
  Vec3 ambient{0.1f, 0.1f, 0.1f};
  std::vector<PointLight> lights;
  std::vector<SceneMaterial> materials;
  std::vector<SceneObject> objects;
  RenderSettings render;
  std::vector<SceneExpectation> expectations;
  std::size_t triangleCount() const;
};

}  // namespace mpr
