// Scene files: a valid scene loads as written; every kind of mistake is
// reported with its line and column and a useful message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::scene_loader_test {
namespace {

std::string errorOf(const std::string& text) {
  try {
    loadSceneText(text, "s.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneLoader, LoadsAValidScene) {
  const Scene s = loadSceneText(R"(
camera: {position: [0, 1, 5], look_at: [0, 1, 0], fov: 50, near: 0.5, far: 20}
ambient: [0.2, 0.2, 0.2]
lights:
  - {position: [1, 3, 1], color: [1, 0.5, 0.25], attenuation: [1, 0.1, 0], radius: 0.3}
materials:
  shiny: {diffuse: [0.5, 0.5, 0.5], specular: [1, 1, 1], roughness: 0.25}
  glass: {kind: refractive, ior: 1.33}
objects:
  - {name: box, primitive: box, translate: [1, 0, 0], scale: 2, material: shiny}
  - {name: pane, primitive: quad, material: glass}
render: {width: 32, height: 24, recursion_depth: 3, profile: mesa, shadows: false}
)", "s.yaml");
  EXPECT_EQ(s.camera.fovY, 50.0f);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].color, Vec3(1, 0.5f, 0.25f));
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), 12u);
  // Box of side 1 scaled by 2 and moved by 1 in x: x from 0 to 2.
  float minX = 1e9f, maxX = -1e9f;
  for (const Vec3& p : s.objects[0].mesh.positions) minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
  EXPECT_EQ(minX, 0.0f);
  EXPECT_EQ(maxX, 2.0f);
  // Eq. (6) of the 1997 paper: exponent 1.999 / 0.25^2 = 31.984, scale 0.0398 * 31.984 = 1.2730.
  const SceneMaterial& shiny = s.materials[static_cast<std::size_t>(s.objects[0].material)];
  EXPECT_NEAR(shiny.shininess, 31.984f, 1e-4f);
  EXPECT_NEAR(shiny.specular.x, 1.27296f, 1e-4f);
  EXPECT_EQ(s.materials[static_cast<std::size_t>(s.objects[1].material)].kind, MaterialKind::Refractive);
  EXPECT_EQ(s.render.width, 32);
  EXPECT_EQ(s.render.profile, "mesa");
  EXPECT_FALSE(s.render.shadows);
}

// Far from the world's origin (scene/camera_origin.hpp): positions are kept
// in double until made relative to the camera, so the model holds them as
// exactly as at the origin; near it the file's numbers are kept as written.
TEST(SceneLoader, AFarSceneIsHeldRelativeToItsCamera) {
  const Scene far = loadSceneText(R"(
camera: {position: [1000000.25, 2000000.5, -3000000.75], look_at: [1000000.25, 2000000.5, -3000010.75]}
lights: [{position: [1000001.5, 2000003.3, -3000002.75]}]
objects: [{primitive: box, translate: [1000000.35, 2000000.5, -3000005.75], scale: 2}]
)", "s.yaml");
  EXPECT_EQ(far.origin, DVec3(1000000.25, 2000000.5, -3000000.75));
  EXPECT_EQ(far.camera.position, Vec3(0.0f));
  EXPECT_EQ(far.camera.lookAt, Vec3(0.0f, 0.0f, -10.0f));
  // 2000003.3 - 2000000.5 in double is 2.8 up to 2e-10: the float nearest
  // 2.8 (as a float, 2000003.3 would be 2000003.25 and the light 0.05 off).
  EXPECT_EQ(far.lights[0].position, Vec3(1.25f, 2.8f, -2.0f));
  float minX = 1e9f, maxX = -1e9f;
  for (const Vec3& p : far.objects[0].mesh.positions) minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
  EXPECT_EQ(minX, -0.9f);
  EXPECT_EQ(maxX, 1.1f);
  const Scene near = loadSceneText("camera: {position: [1000, 2, 3]}\nlights: [{position: [1000.1, 3, 1]}]\n", "s.yaml");
  EXPECT_EQ(near.origin, DVec3(0.0));
  EXPECT_EQ(near.camera.position, Vec3(1000.0f, 2.0f, 3.0f));
  EXPECT_EQ(near.lights[0].position, Vec3(1000.1f, 3.0f, 1.0f));
}

TEST(SceneLoader, OverridesApplyBeforeValidation) {
  const Scene s = loadSceneText("render: {width: 64}\n", "s.yaml", {"render.width=20", "render.height=10", "camera.fov=30"});
  EXPECT_EQ(s.render.width, 20);
  EXPECT_EQ(s.render.height, 10);
  EXPECT_EQ(s.camera.fovY, 30.0f);
  EXPECT_THROW(loadSceneText("", "s.yaml", {"render.width"}), SceneError);
  // Errors in a --set value name the option, not a line of the file.
  try {
    loadSceneText("render: {width: 64}\n", "s.yaml", {"render.width=abc"});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "--set render.width=abc:1:1: render.width must be a number, not 'abc'");
  }
  try {
    loadSceneText("", "s.yaml", {"render.widht=3"});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "--set render.widht=3:1:1: unknown key 'widht' in render; did you mean 'width'?");
  }
}

TEST(SceneLoader, ErrorsNameLineColumnAndSuggest) {
  EXPECT_EQ(errorOf("camera:\n  positon: [0, 1, 2]\n"),
            "s.yaml:2:3: unknown key 'positon' in camera; did you mean 'position'?");
  EXPECT_EQ(errorOf("camra: {}\n"), "s.yaml:1:1: unknown key 'camra' in the scene; did you mean 'camera'?");
  EXPECT_EQ(errorOf("render:\n  width: wide\n"), "s.yaml:2:10: render.width must be a number, not 'wide'");
  EXPECT_EQ(errorOf("render:\n  width: 1.5\n"), "s.yaml:2:10: render.width must be an integer, not 1.5");
  EXPECT_EQ(errorOf("render:\n  refraction_map: sideways\n"),
            "s.yaml:2:19: unknown refraction_map 'sideways' (known: projection, projection_zeroed_z, end_of_pipeline)");
  EXPECT_EQ(errorOf("ambient: [0, .nan, 0]\n"), "s.yaml:1:14: ambient[1] must be finite, not '.nan'");
  EXPECT_EQ(errorOf("ambient: [0, 1]\n"), "s.yaml:1:10: ambient must be a list of 3 numbers, like [0, 1, 0]");
  EXPECT_EQ(errorOf("camera: {position: [0, 0, 0], look_at: [0, 0, 0]}\n"),
            "s.yaml:1:40: camera.look_at must differ from camera.position");
  EXPECT_EQ(errorOf("materials:\n  g: {kind: refractive, ior: 0}\n"),
            "s.yaml:2:30: material 'g' ior (index of refraction) must be greater than 0, not 0");
  EXPECT_EQ(errorOf("materials:\n  g: {kind: glassy}\n"),
            "s.yaml:2:13: material 'g' kind must be diffuse, mirror, refractive, translucent or frosted, not 'glassy'");
  EXPECT_EQ(errorOf("objects:\n  - {primitive: box, material: shinny}\nmaterials: {shiny: {}}\n"),
            "s.yaml:2:32: object 'object at line 2' uses unknown material 'shinny'; did you mean 'shiny'?");
  EXPECT_EQ(errorOf("objects:\n  - {primitive: torus}\n"),
            "s.yaml:2:17: object 'object at line 2' primitive must be box, sphere, cylinder, quad or plane, not 'torus'");
  EXPECT_EQ(errorOf("objects:\n  - {name: a}\n"), "s.yaml:2:5: object 'a' needs a primitive or a mesh");
  EXPECT_EQ(errorOf("render: {recursion_depth: 128}\n"),
            "s.yaml:1:27: render.recursion_depth 128 needs more stencil levels than the 8-bit stencil of profile "
            "'indigo' holds: recursion levels lie below SHAD_MIN = 128, so the deepest is 127");
  EXPECT_EQ(errorOf("materials:\n  m: {roughness: 0.1}\n"),
            "s.yaml:2:18: material 'm' roughness must be at least 0.125: eq. (6) gives a Phong exponent of "
            "1.999/alpha^2, and GL's largest is 128");
  EXPECT_EQ(errorOf("camera: [1, 2\n"), "s.yaml:2:1: YAML syntax: end of sequence flow not found");
  EXPECT_EQ(errorOf("materials:\n  m: {kind: mirror, thickness: 0.1}\n"),
            "s.yaml:2:32: material 'm' thickness is for refracting materials (kind refractive, translucent or "
            "frosted): a slab shifts the view through it; this one is not looked through");
  // darkness_levels: the levels in the accumulation buffer, every sample counted above SHAD_ZERO.
  const std::string soft = "lights: [{position: [0, 4, 0], radius: 1}]\nrender: {soft_shadow_method: darkness_levels, ";
  EXPECT_EQ(errorOf(soft + "soft_shadow_samples: 64}\n"),
            "s.yaml:2:30: render.soft_shadow_method darkness_levels counts all 64 light samples' shadow volumes in one "
            "stencil: the 8-bit stencil of profile 'indigo' counts at most 63 above SHAD_ZERO (use "
            "soft_shadow_samples <= 63 or the images method)");
  EXPECT_EQ(errorOf(soft + "soft_shadow_samples: 4, antialias_samples: 4}\n"),
            "s.yaml:2:30: render.soft_shadow_method darkness_levels sums its levels in the accumulation buffer, which "
            "render.antialias_samples 4 needs for its images: one accumulation buffer holds one sum (use the images "
            "method, or render.frosted: false / antialias_samples: 1)");
  EXPECT_EQ(errorOf("render: {soft_shadow_method: penumbra}\n"),
            "s.yaml:1:30: unknown soft_shadow_method 'penumbra' (known: images, darkness_levels, pivot)");
  // Without a light radius there are no levels, so no limit of theirs to
  // refuse: what is refused is the samples, with nothing to sample (issue 43).
  EXPECT_EQ(errorOf("render: {soft_shadow_method: darkness_levels, soft_shadow_samples: 64, antialias_samples: 4}\n"),
            "s.yaml:1:68: render.soft_shadow_samples 64 samples the lights that have a radius, and no light here has "
            "one (give a light a radius for soft shadows)");
}

// Issue 48: a quoted scalar is a string wherever it stands. yaml-cpp hands
// '45' over with the text of 45, and the loader read it as the number.
TEST(SceneLoader, QuotedNumbersAndBooleansAreRefused) {
  EXPECT_EQ(errorOf("camera: {fov: '45'}\n"),
            "s.yaml:1:15: camera.fov must be a number, not the quoted string '45' (write it without quotes)");
  EXPECT_EQ(errorOf("render:\n  width: \"20\"\n"),
            "s.yaml:2:10: render.width must be a number, not the quoted string '20' (write it without quotes)");
  EXPECT_EQ(errorOf("ambient: [0, '1', 0]\n"),
            "s.yaml:1:14: ambient[1] must be a number, not the quoted string '1' (write it without quotes)");
  EXPECT_EQ(errorOf("lights: [{position: [0, 1, 0], radius: '0.5'}]\n"),
            "s.yaml:1:40: light radius must be a number, not the quoted string '0.5' (write it without quotes)");
  EXPECT_EQ(errorOf("objects: [{primitive: box, scale: '2'}]\n"),
            "s.yaml:1:35: object 'object at line 1' scale must be a number, not the quoted string '2' (write it "
            "without quotes)");
  EXPECT_EQ(errorOf("render: {shadows: 'false'}\n"),
            "s.yaml:1:19: render.shadows must be true or false, not the quoted string 'false' (write it without quotes)");
  EXPECT_EQ(errorOf("render: {width: !!str 20}\n"),
            "s.yaml:1:17: render.width must be a number, not a value tagged 'tag:yaml.org,2002:str'");
  EXPECT_EQ(errorOf("expect: [{after: end, stencil: [0, 0], value: '3'}]\n"),
            "s.yaml:1:47: expect stencil value must be a number, not the quoted string '3' (write it without quotes)");
  // A --set value is YAML too: quoted there, it is a string.
  try {
    loadSceneText("", "s.yaml", {"camera.fov='45'"});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "--set camera.fov='45':1:1: camera.fov must be a number, not the quoted string '45' (write it without quotes)");
  }
  // Plain and explicitly numeric scalars, and quoted text where text belongs, load.
  const Scene s = loadSceneText(
      "camera: {fov: !!float 40}\nlights: [{position: [0, 3, 0]}]\nrender: {width: 20, shadows: false, profile: 'mesa'}\n"
      "expect: [{after: 'end', stencil: [0, 0], value: 'SHAD_ZERO + 1'}]\n",
      "s.yaml");
  EXPECT_EQ(s.camera.fovY, 40.0f);
  EXPECT_EQ(s.render.width, 20);
  EXPECT_EQ(s.render.profile, "mesa");
  EXPECT_EQ(s.expectations[0].probe.expected[0], 193);
}

// Issue 48: the field of view the format promises, (0, 180), with the
// smallest that renders correctly (kMinFieldOfView): 1e-50 was zero as a
// float (no projection at all), 180 a projection of everything onto the
// centre, 1e-8 black bands.
TEST(SceneLoader, FieldOfViewIsHeldToWhatRenders) {
  EXPECT_EQ(errorOf("camera: {fov: 180}\n"), "s.yaml:1:15: camera.fov must be below 180, not 180");
  EXPECT_EQ(errorOf("camera: {fov: 179.999999999}\n"),
            "s.yaml:1:15: camera.fov must be below 180, not 179.999999999 (180 as a float)");
  EXPECT_EQ(errorOf("camera: {fov: 0}\n"),
            "s.yaml:1:15: camera.fov must be at least 0.05 degrees (narrower, float rounding in clipping leaves bands of the window empty), not 0");
  EXPECT_EQ(errorOf("camera: {fov: 1e-50}\n"),
            "s.yaml:1:15: camera.fov must be at least 0.05 degrees (narrower, float rounding in clipping leaves bands of the window empty), not 1e-50");
  EXPECT_EQ(errorOf("camera: {fov: 1e-8}\n"),
            "s.yaml:1:15: camera.fov must be at least 0.05 degrees (narrower, float rounding in clipping leaves bands of the window empty), not 1e-8");
  EXPECT_EQ(errorOf("camera: {fov: -5}\n"),
            "s.yaml:1:15: camera.fov must be at least 0.05 degrees (narrower, float rounding in clipping leaves bands of the window empty), not -5");
  EXPECT_EQ(errorOf("camera: {fov: 0.0499}\n"),
            "s.yaml:1:15: camera.fov must be at least 0.05 degrees (narrower, float rounding in clipping leaves bands of "
            "the window empty), not 0.0499");
  EXPECT_EQ(loadSceneText("camera: {fov: 0.05}\n", "s.yaml").camera.fovY, 0.05f);
  EXPECT_EQ(loadSceneText("camera: {fov: 179.9}\n", "s.yaml").camera.fovY, 179.9f);
}

// Issue 48: YAML::Load read the first document and dropped the rest.
TEST(SceneLoader, ASecondDocumentIsRefusedWhereItStarts) {
  EXPECT_EQ(errorOf("render: {width: 32}\n---\nrender: {width: 8}\n"),
            "s.yaml:2:1: a second YAML document starts here; a scene file holds one (remove this '---' and what "
            "follows, or merge it into the first)");
  EXPECT_EQ(errorOf("---\nrender: {width: 32}\n--- # more\n"),
            "s.yaml:3:1: a second YAML document starts here; a scene file holds one (remove this '---' and what "
            "follows, or merge it into the first)");
  EXPECT_EQ(errorOf("render: {width: 32}\n...\nrender: {width: 8}\n"),
            "s.yaml:3:1: a second YAML document starts here; a scene file holds one (remove this '---' and what "
            "follows, or merge it into the first)");
  // A syntax error in the second document is found too (it was never read).
  EXPECT_EQ(errorOf("render: {width: 32}\n---\n[1, 2\n"), "s.yaml:4:1: YAML syntax: end of sequence flow not found");
  // One document, with its start and end marked, loads; so does an empty file.
  EXPECT_EQ(loadSceneText("---\nrender: {width: 32}\n...\n", "s.yaml").render.width, 32);
  EXPECT_EQ(loadSceneText("# nothing\n", "s.yaml").render.width, 640);
}

// A UTF-8 byte-order mark before the first key: yaml-cpp skips it, and the
// columns of line 1 count from after it.
TEST(SceneLoader, ALeadingByteOrderMarkIsSkipped) {
  EXPECT_EQ(loadSceneText("\xEF\xBB\xBFrender: {width: 32}\n", "s.yaml").render.width, 32);
  EXPECT_EQ(errorOf("\xEF\xBB\xBFrender: {width: x}\n"), "s.yaml:1:17: render.width must be a number, not 'x'");
}

// Issue 48: a --set path enters a list by index (objects.0.scale), and an
// error in what a --set gave or made names that --set, never the file.
TEST(SceneLoader, SetEntersListsAndItsErrorsNameIt) {
  const std::string two = "objects:\n  - {primitive: box}\n  - {primitive: sphere, subdivisions: 4}\n";
  const Scene s = loadSceneText(two, "s.yaml", {"objects.0.scale=2", "objects.1.translate=[0, 0, 5]"});
  ASSERT_EQ(s.objects.size(), 2u);
  float maxX = -1e9f, minZ = 1e9f;
  for (const Vec3& p : s.objects[0].mesh.positions) maxX = std::max(maxX, p.x);
  for (const Vec3& p : s.objects[1].mesh.positions) minZ = std::min(minZ, p.z);
  EXPECT_EQ(maxX, 1.0f);  // a unit box (half-side 0.5) scaled by 2
  EXPECT_EQ(minZ, 4.0f);  // a sphere of radius 1 moved to z = 5
  const auto setError = [&](const std::string& set) {
    try {
      loadSceneText(two, "s.yaml", {set});
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(setError("objects.0.scale=0"), "--set objects.0.scale=0:1:1: object 'object at line 2' scale must not be zero");
  EXPECT_EQ(setError("objects.2.scale=2"),
            "--set objects.2.scale=2:1:9: objects is a list of 2 entries: give an index from 0 to 1, not '2'");
  EXPECT_EQ(setError("objects.first.scale=2"),
            "--set objects.first.scale=2:1:9: objects is a list of 2 entries: give an index from 0 to 1, not 'first'");
  // scale is not in the file: the path makes a mapping, whose error is the --set's.
  EXPECT_EQ(setError("objects.0.scale.x=2"),
            "--set objects.0.scale.x=2:1:1: object 'object at line 2' scale must be a list of 3 numbers, like [0, 1, 0]");
  EXPECT_EQ(setError("objects.0.primitive.x=2"),
            "--set objects.0.primitive.x=2:1:21: objects.0.primitive is a value ('box'), not a mapping with a key 'x'");
  EXPECT_EQ(setError("render..width=2"),
            "--set render..width=2:1:8: 'render..width' has an empty key; keys are joined by single dots");
  // Inside a value a --set gave: its line and column are the value's, not the file's.
  EXPECT_EQ(setError("camera={fov: 200}"), "--set camera={fov: 200}:1:1: camera.fov must be below 180, not 200");
  EXPECT_EQ(setError("objects.1={primitive: cube}"),
            "--set objects.1={primitive: cube}:1:1: object 'object 1 of the list' primitive must be box, sphere, "
            "cylinder, quad or plane, not 'cube'");
  // A mapping a --set made on its way.
  EXPECT_EQ(setError("materials.m.kind=mirror"), "no error");
  EXPECT_EQ(setError("camera.fov=30"), "no error");
}

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    // A fresh folder per test: CTest runs each test as its own process, in
    // parallel, and a shared name let one test's TearDown remove another's files.
    std::string t = (std::filesystem::temp_directory_path() / "mpr_scene_test_XXXXXX").string();
    ASSERT_NE(mkdtemp(t.data()), nullptr);
    dir_ = t;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string errorOfFile(const std::string& yaml) {
    const std::string path = write("scene.yaml", yaml);
    try {
      loadSceneFile(path);
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      return msg.substr(msg.find(".yaml:") + 6);  // drop the temporary folder
    }
    return "no error";
  }
  std::filesystem::path dir_;
};

TEST_F(MeshFiles, MeshesLoadRelativeToTheScene) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\n");
  const std::string path = write("scene.yaml", "objects:\n  - {mesh: tri.obj, translate: [0, 0, 1]}\n");
  const Scene s = loadSceneFile(path);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].mesh.faces.size(), 1u);
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), 2u);
  EXPECT_EQ(s.objects[0].mesh.positions[0].z, 1.0f);
}

TEST_F(MeshFiles, MissingAndUnreadableMeshes) {
  EXPECT_NE(errorOfFile("objects:\n  - {name: m, mesh: nothere.obj}\n").find("2:21: object 'm': mesh file '"), std::string::npos);
  write("junk.obj", "this is not a mesh\n");
  EXPECT_NE(errorOfFile("objects:\n  - {name: m, mesh: junk.obj}\n").find("2:21: object 'm': mesh file"), std::string::npos);
}

TEST_F(MeshFiles, SpecularObjectsNeedPlanarFacesWithArea) {
  write("bent.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nf 1 2 3 4\n");
  write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  const std::string mats = "materials: {m: {kind: mirror}}\n";
  EXPECT_NE(errorOfFile(mats + "objects:\n  - {name: bent, mesh: bent.obj, material: m}\n").find("has a non-planar face (face 0"),
            std::string::npos);
  EXPECT_NE(errorOfFile(mats + "objects:\n  - {name: flat, mesh: flat.obj, material: m}\n").find("has a zero-area face (face 0)"),
            std::string::npos);
  // The same bent face is fine on a diffuse object.
  EXPECT_EQ(errorOfFile("objects:\n  - {name: bent, mesh: bent.obj}\n"), "no error");
}

// Issue 48: OpenMesh wrote its own lines to standard error ("ImporterT:
// Face has equal vertices", "PolyMeshT::add_face: complex edge") and OBJ
// and STL faces it dropped went unmentioned; now MPR says it, once a mesh,
// at the object's mesh key.
TEST_F(MeshFiles, DroppedAndNonManifoldFacesAreMPRsWarnings) {
  write("d.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 0 1\n2 0 1\n3 0 2 3\n");
  write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 1 1 2\nf 2 4 3\nf 2 4 3\n");
  write("clean.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string path =
      write("scene.yaml", "objects:\n  - {name: a, mesh: d.off}\n  - {name: b, mesh: d.obj}\n  - {name: c, mesh: clean.obj}\n");
  ::testing::internal::CaptureStderr();
  const Scene s = loadSceneFile(path);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.objects[0].mesh.faces.size(), 2u);
  EXPECT_EQ(s.objects[1].mesh.faces.size(), 3u);
  const std::string d = dir_.string();
  EXPECT_EQ(err, path + ":2:21: warning: object 'a': mesh file '" + d + "/d.off': 2 of its 4 faces dropped as degenerate "
                 "(fewer than three corners, or a corner repeated)\n" +
                 path + ":3:21: warning: object 'b': mesh file '" + d + "/d.obj': 1 of its 4 faces dropped as degenerate "
                 "(fewer than three corners, or a corner repeated)\n" +
                 path + ":3:21: warning: object 'b': mesh file '" + d + "/d.obj': 1 non-manifold face kept with vertices "
                 "of its own (not smoothed with its neighbours)\n");
  // A scene that fails says only why.
  ::testing::internal::CaptureStderr();
  EXPECT_NE(errorOfFile("objects:\n  - {name: a, mesh: d.off}\n  - {primitive: torus}\n"), "no error");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(SceneLoader, DefaultSceneLoadsAndDescribeNamesEveryKey) {
  const Scene s = loadSceneText(defaultSceneText(), "<default>");
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_GE(s.objects.size(), 6u);
  const std::string d = describeSceneFormat();
  for (const char* k : {"\"camera\"", "\"look_at\"", "\"roughness\"", "\"fog_distance\"", "\"recursion_depth\"", "\"subdivisions\""})
    EXPECT_NE(d.find(k), std::string::npos) << k;
}

}  // namespace
}  // namespace mpr::scene_loader_test
