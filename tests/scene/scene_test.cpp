// Scene files (common/scene/scene.cpp): every key read, refusals with the file and JSON path,
// relative paths, built-in scenes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "common/core/passes.hpp"
#include "common/mesh/procedural.hpp"
#include "common/scene/scene.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

using testing::TempDir;

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(SceneFile, ReadsEveryKey) {
  TempDir tmp;
  tmp.write("tri.obj", kTriangleObj);
  std::string path = tmp.write("s.json", R"({
    "objects": [{"mesh": "tri.obj", "transform": [2,0,0,0, 0,2,0,0, 0,0,2,0, 1,2,3,1],
                 "style": "sketchy", "color": [0.5, 0.25, 1], "flat": true},
                {"mesh": "tri.obj"}],
    "camera": {"eye": [0, 0, 9], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 50, "near": 0.5, "far": 30},
    "lights": [{"direction": [0, 0, 1], "intensity": 0.5}],
    "resolution": [320, 200], "seed": 42, "effects": ["contours"],
    "params": {"edge.depth_scale": 12, "edge.normals": "face"}})");
  Scene s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].mesh, s.objects[1].mesh) << "a file named twice is loaded once";
  // Column-major: the translation is elements 12..14. Positions are relative to the
  // scene's origin (and the mesh is centered), so compare world positions.
  auto world = [&](const SceneObject& o, size_t v) {
    return glm::dvec3(o.transform * glm::vec4(o.mesh->positions[v], 1.0f)) + s.origin;
  };
  const glm::dvec3 expected[3] = {{1, 2, 3}, {3, 2, 3}, {1, 4, 3}};  // 2 (0 0 0), 2 (1 0 0), 2 (0 1 0), + (1 2 3)
  for (size_t v = 0; v < 3; ++v) {
    EXPECT_NEAR(glm::distance(world(s.objects[0], v), expected[v]), 0.0, 1e-6) << v;
    EXPECT_NEAR(glm::distance(2.0 * world(s.objects[1], v), expected[v] - glm::dvec3(1, 2, 3)), 0.0, 1e-6) << v;
  }
  EXPECT_EQ(s.objects[0].style, Style::Sketchy);
  EXPECT_EQ(s.objects[0].color, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_TRUE(s.objects[0].flat);
  EXPECT_EQ(glm::dvec3(s.camera.eye) + s.origin, glm::dvec3(0, 0, 9));
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 50);
  EXPECT_FLOAT_EQ(s.camera.near, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.far, 30);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 0.5f);
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 200);
  EXPECT_EQ(s.seed, 42u);
  EXPECT_DOUBLE_EQ(s.params.value("edge.depth_scale"), 12);
  EXPECT_DOUBLE_EQ(s.params.value("edge.normals"), 1);
}

TEST(SceneFile, FittedCameraSeesTheWholeScene) {
  Scene s = parse_scene(R"({"mesh": {"procedural": "torus"}})", "t.json", ".");
  glm::vec3 c;
  float r;
  scene_bounds(s, c, r);
  EXPECT_LT(s.camera.near, glm::length(c - s.camera.eye) - r);
  EXPECT_GT(s.camera.far, glm::length(c - s.camera.eye) + r);
  EXPECT_FALSE(s.lights.empty());
}

std::string refusal(const std::string& json, const std::string& base = ".") {
  try {
    parse_scene(json, "bad.json", base);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SceneFile, RefusalsNameTheFileAndJsonPath) {
  const std::map<std::string, std::string> cases = {
      {R"({"mesh": {"procedural": "torus"}, "colour": 1})", "bad.json: /colour: unknown key"},
      {R"({"mesh": {"procedural": "torus"}, "camera": {"fov_deg": "wide"}})",
       "bad.json: /camera/fov_deg: expected a number"},
      {R"({"mesh": {"procedural": "torus"}, "effects": ["contours", "oil"]})",
       "bad.json: /effects/1: unknown effect 'oil'"},
      {R"({"mesh": {"procedural": "torus"}, "params": {"edge.depth_scale": -1}})",
       "bad.json: /params/edge.depth_scale:"},
      {R"({"mesh": {"procedural": "torus"}, "params": {"edge.nope": 1}})",
       "bad.json: /params/edge.nope: unknown parameter"},
      {R"({"mesh": {"procedural": "donut"}})", "bad.json: /mesh: unknown procedural mesh 'donut'"},
      {R"({"objects": [{"mesh": "nowhere.obj"}]})", "bad.json: /objects/0/mesh:"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [1, 2]}]})", "bad.json: /objects/0/transform:"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "oil"}]})", "bad.json: /objects/0/style:"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [0, 10]})", "bad.json: /resolution/0: must be in 1..16384"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [10, 4294967396]})", "bad.json: /resolution/1: must be in"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [800.5, 10]})", "bad.json: /resolution: expected"},
      {R"({"mesh": 7})", "bad.json: /mesh: expected a mesh file path"},
      {R"({"mesh": {"procedural": "torus", "decimate_to": 3}})",
       "bad.json: /mesh/decimate_to: expected a whole number of faces in 4..100000000"},
      {R"({"mesh": {"procedural": "torus", "decimate_to": 100.5}})", "bad.json: /mesh/decimate_to: expected a whole"},
      {R"({"mesh": {"procedural": "torus", "decimate_to": 1e9}})", "bad.json: /mesh/decimate_to: expected a whole"},
      {R"({"mesh": {"file": "a.obj", "procedural": "torus"}})", "bad.json: /mesh: give either \"file\" or"},
      {R"({"mesh": {"decimate_to": 100}})", "bad.json: /mesh: give either \"file\" or"},
      {R"({"mesh": {"file": "a.obj", "resolution": 2}})", "bad.json: /mesh/resolution: applies to a procedural"},
      {R"({"mesh": {"file": 7}})", "bad.json: /mesh/file: expected a mesh file path"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "color": [1, 2, 0]}]})",
       "bad.json: /objects/0/color/1: must be in [0, 1]"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "flat": 1}]})",
       "bad.json: /objects/0/flat: expected true or false"},
      {R"({"objects": [{"mesh": {"procedural": "torus", "resolution": 99}}]})",
       "bad.json: /objects/0/mesh: procedural resolution"},
      {R"({"mesh": {"procedural": "torus"}, "camera": {"eye": [1, 2]}})",
       "bad.json: /camera/eye: expected an array of 3 numbers"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 1], "power": 2}]})",
       "bad.json: /lights/0/power: unknown key"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 0]}]})", "bad.json: /lights/0/direction:"},
      {R"({"mesh": {"procedural": "torus"}, "seed": -3})", "bad.json: /seed:"},
      {R"({"mesh": {"procedural": "torus"}, "camera": {"near": 5, "far": 1}})",
       "bad.json: /camera/far: near 5 and far 1"},
      {R"({"mesh": {"procedural": "torus"}, "objects": []})", "bad.json: /: give either"},
      {R"({})", "bad.json: /: give either"},
      {"{\n  \"mesh\": 1,,\n}", "bad.json: line 2, column 13"},
  };
  for (const auto& [json, expected] : cases) {
    std::string m = refusal(json);
    EXPECT_NE(m.find(expected), std::string::npos) << "scene " << json << "\n gave: " << m;
  }
}

// A camera that float buffers cannot render is refused with the key at fault, and one
// the scene does not give with where it came from (docs/bad-input.md).
TEST(SceneFile, CamerasFloatCannotRenderAreRefused) {
  const std::string torus = R"({"mesh": {"procedural": "torus"}, "camera": )";
  const std::map<std::string, std::string> cases = {
      {R"({"near": 0, "far": 10})", "/camera/near: is 0: it must be greater than 0"},
      {R"({"near": -1, "far": 10})", "/camera/near: is -1"},
      {R"({"near": 2, "far": 2})", "/camera/far: near 2 and far 2: far must be greater than near"},
      {R"({"near": 1e-7, "far": 10})", "/camera/near: near 1e-07 and far 10: far / near is over the 1e+06"},
      {R"({"near": 1e-44, "far": 10})", "/camera/near:"},
      {R"({"near": 100, "far": 100.01})", "/camera/far: near 100 and far 100.01: float depth cannot tell them apart"},
      {R"({"fov_deg": 0})", "/camera/fov_deg: must be in (0, 180) degrees"},
      {R"({"fov_deg": 180})", "/camera/fov_deg: must be in (0, 180) degrees"},
      {R"({"fov_deg": -5})", "/camera/fov_deg: must be in (0, 180) degrees"},
      {R"({"fov_deg": 1e-30})", "/camera/fov_deg: gives a field of view of 1e-30 degrees, under the 0.001"},
      {R"({"eye": [1, 2, 3], "target": [1, 2, 3]})", "/camera/target: coincides with the eye"},
      {R"({"eye": [0, 0, 0]})", "/camera/target: coincides with the eye (the scene's center)"},
      {R"({"eye": [0, 0, 1e-20], "target": [0, 0, 0], "up": [0, 1, 0]})",
       "/camera/target: lies 1e-20 from the eye, under the 1e-18 a view direction needs"},
      {R"({"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, -2, 0]})", "/camera/up: is parallel"},
      {R"({"eye": [0, 5, 0], "target": [0, 0, 0], "up": [1e-4, 1, 0]})", "/camera/up: is parallel"},
      {R"({"eye": [0, 5, 0]})",
       "/camera/up: is parallel (or nearly) to the view direction, target - eye (the default up)"},
      {R"({"eye": [0, 5, 0], "up": [0, 0, 0]})", "/camera/up: has length 0"},
      {R"({"eye": [1e20, 0, 0]})", "/camera/eye: lies at (1e+20, 0, 0), beyond ±1e+09"},
      {R"({"eye": [0, 0, 5], "target": [0, -2e9, 0]})", "/camera/target: lies at (0, -2e+09, 0), beyond ±1e+09"},
      {R"({"eye": [1e8, 0, 0]})",
       "/camera/far: near 1e+08 and far 1e+08: far must be greater than near (fitted to the scene"},
      {R"({"eye": [1e5, 0, 0]})", "/camera/far: near 99997 and far 100003: float depth cannot tell them apart"},
      {R"({"fov_deg": 0.01})", "/camera/far: "},
      {R"({"view_direction": [1e-30, 0, 0]})", "/camera/view_direction: has length 1e-30, outside [1e-18, 1e+18]"},
      {R"({"eye": [1e39, 0, 0]})", "/camera/eye/0: 1e+39 is beyond float range"},
      {R"({"fov_deg": 3e39})", "/camera/fov_deg: 3e+39 is beyond float range"},
  };
  for (const auto& [camera, expected] : cases) {
    std::string m = refusal(torus + camera + "}");
    EXPECT_NE(m.find("bad.json: " + expected), std::string::npos) << "camera " << camera << "\n gave: " << m;
    EXPECT_EQ(m.find("nan"), std::string::npos) << "camera " << camera << "\n gave: " << m;
  }
  // A camera fitted to a scene too large for its field of view would stand beyond the bound.
  EXPECT_NE(refusal(R"({"objects": [{"mesh": {"procedural": "torus"},
                       "transform": [4e8,0,0,0, 0,4e8,0,0, 0,0,4e8,0, 0,0,0,1]}]})")
                .find("bad.json: /camera/eye: lies at"),
            std::string::npos);
}

// Values beyond what float holds, or whose products overflow it, are refused with the key;
// a number beyond double range with the line and column.
TEST(SceneFile, ValuesBeyondFloatAreRefused) {
  const std::map<std::string, std::string> cases = {
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 1], "intensity": 1e39}]})",
       "/lights/0/intensity: 1e+39 is beyond float range"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 1], "intensity": 3e38}]})",
       "/lights/0/intensity: must be in [0, 1e+06]"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [3e38, 0, 0]}]})",
       "/lights/0/direction: has length 3e+38, outside"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [1,0,0,0, 0,1,0,0, 0,0,1,0, 3e38,0,0,1]}]})",
       "/objects/0/transform: moves vertex 0 to (3e+38, "},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1e39,0,0,1]}]})",
       "/objects/0/transform/12: 1e+39 is beyond float range"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [1e9,0,0,0, 0,1e9,0,0, 0,0,1e9,0, 0,0,0,1]}]})",
       "/objects/0/transform: moves vertex"},
      {R"({"objects": [{"mesh": {"procedural": "torus"},
                         "transform": [1e12,0,0,0, 0,1e12,0,0, 0,0,1e12,0, 0,0,0,1]}]})",
       "/objects/0/transform: scales volumes by 1e+36, outside"},
      {R"({"objects": [{"mesh": {"procedural": "torus"},
                         "transform": [1e-12,0,0,0, 0,1e-12,0,0, 0,0,1e-12,0, 0,0,0,1]}]})",
       "/objects/0/transform: scales volumes by 1e-36, outside"},
      {"{\"mesh\": {\"procedural\": \"torus\"},\n \"seed\": 1,\n \"camera\": {\"far\": 1e400}}",
       "bad.json: line 3, column 24: cannot read the JSON ([json.exception.out_of_range.406] number overflow"},
  };
  for (const auto& [json, expected] : cases) {
    std::string m = refusal(json);
    EXPECT_NE(m.find(expected), std::string::npos) << "scene " << json << "\n gave: " << m;
  }
}

TEST(SceneFile, MeshCoordinatesBeyondTheBoundAreRefused) {
  TempDir tmp;
  tmp.write("far.obj", "v 0 0 0\nv 2e9 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(refusal(R"({"mesh": "far.obj"})", tmp.dir())
                .find("bad.json: /mesh: vertex 1 lies at (2e+09, 0, 0), beyond ±1e+09"),
            std::string::npos);
}

// The singular test is relative: a uniform scale of any size within the bounds passes, a
// transform that (nearly) flattens the mesh does not; the last row must be 0, 0, 0, 1.
TEST(SceneFile, TransformsAreCheckedRelativeToTheirScale) {
  for (const char* t : {"1e-4,0,0,0, 0,1e-4,0,0, 0,0,1e-4,0, 0,0,0,1", "1e4,0,0,0, 0,1e4,0,0, 0,0,1e4,0, 0,0,0,1",
                        "0,1e-4,0,0, -1e-4,0,0,0, 0,0,1e-4,0, 5,5,5,1", "1e-9,0,0,0, 0,1e-9,0,0, 0,0,1e-9,0, 0,0,0,1",
                        "1,0,0,0, 0,1,0,0, 0,0,1e-3,0, 0,0,0,1"}) {
    std::string json = std::string(R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [)") + t + "]}]}";
    EXPECT_EQ(refusal(json), "accepted") << t;
  }
  const std::map<std::string, std::string> cases = {
      {"1,0,0,0, 0,1,0,0, 0,0,0,0, 0,0,0,1", "/objects/0/transform: is singular"},
      {"1,0,0,0, 1,0,0,0, 0,0,1,0, 0,0,0,1", "/objects/0/transform: is singular"},
      {"1,0,0,0, 0,1,0,0, 0,0,1e-7,0, 0,0,0,1",
       "/objects/0/transform: is nearly singular: its linear part's condition"},
      {"1,0,0,0, 1,1e-7,0,0, 0,0,1,0, 0,0,0,1", "/objects/0/transform: is nearly singular"},
      {"1,0,0,0.5, 0,1,0,0, 0,0,1,0, 0,0,0,1", "/objects/0/transform/3: must be 0 (the last row"},
      {"1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,2", "/objects/0/transform/15: must be 1"},
  };
  for (const auto& [t, expected] : cases) {
    std::string m = refusal(R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [)" + t + "]}]}");
    EXPECT_NE(m.find("bad.json: " + expected), std::string::npos) << t << "\n gave: " << m;
  }
}

TEST(SceneFile, MissingFileIsRefusedWithItsName) {
  TempDir tmp;
  try {
    load_scene(tmp.path("absent.json"));
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.json: cannot read"), std::string::npos) << e.what();
  }
}

TEST(SceneFile, RelativeMeshPathsResolveAgainstTheSceneFolder) {
  TempDir tmp;
  std::filesystem::create_directories(tmp.path("meshes"));
  tmp.write("meshes/tri.obj", kTriangleObj);
  std::filesystem::create_directories(tmp.path("scenes"));
  std::string path = tmp.write("scenes/s.json", R"({"mesh": "../meshes/tri.obj"})");
  EXPECT_EQ(load_scene(path).objects.at(0).mesh->triangles.size(), 1u);
  EXPECT_NE(refusal(R"({"mesh": "../meshes/tri.obj"})", tmp.dir()).find("/mesh"), std::string::npos);
}

TEST(BuiltinScenes, EachHasOneObjectAndAFittedCamera) {
  for (const auto& name : builtin_scene_names()) {
    Scene s = builtin_scene(name);
    EXPECT_EQ(s.objects.size(), 1u) << name;
    EXPECT_GT(s.camera.far, s.camera.near) << name;
  }
  EXPECT_THROW(builtin_scene("teapot"), SceneError);
}

// Every example scene loads (those of a shared model only where the model is there).
TEST(SceneFile, ExampleScenesLoad) {
  size_t loaded = 0;
  std::string skipped;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes")) {
    std::string path = entry.path().string();
    if (entry.path().extension() != ".json" || path.ends_with(".schema.json")) continue;
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    if (text.find("shared/models/") != std::string::npos && !std::filesystem::exists(PLUMBAGO_MODELS_DIR)) {
      skipped += std::string(skipped.empty() ? "" : ", ") + entry.path().filename().string();
      continue;
    }
    Scene s = load_scene(path);
    EXPECT_FALSE(s.objects.empty()) << path;
    ++loaded;
  }
  EXPECT_GE(loaded, 2u);  // at least the procedural ones
  if (!skipped.empty()) GTEST_SKIP() << "shared models not here (../shared/models is absent): not loaded " << skipped;
}

// The JSON Schema names the same procedural kinds as the program; the effects, which the
// stages declare, it leaves to `plumbago effects` rather than keep a copy of the list.
TEST(SceneFile, SchemaListsTheProgramsKindsAndPointsToTheEffects) {
  std::ifstream in(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/scene.schema.json");
  nlohmann::json schema = nlohmann::json::parse(in);
  EXPECT_FALSE(schema["properties"]["effects"]["items"].contains("enum"));
  EXPECT_NE(schema["properties"]["effects"]["description"].get<std::string>().find("plumbago effects"),
            std::string::npos);
  EXPECT_EQ(schema["$defs"]["mesh"]["oneOf"][1]["properties"]["procedural"]["enum"].get<std::vector<std::string>>(),
            procedural_kinds());
}

}  // namespace
}  // namespace plumbago
