// Scene files (common/scene.cpp): every key read, refusals with the file and JSON path,
// relative paths, built-in scenes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "common/passes.hpp"
#include "common/procedural.hpp"
#include "common/scene.hpp"
#include "tests/temp_dir.hpp"

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
  EXPECT_EQ(s.objects[0].transform[3][0], 1.0f);  // column-major: translation in elements 12..14
  EXPECT_EQ(s.objects[0].transform[3][2], 3.0f);
  EXPECT_EQ(s.objects[0].style, Style::Sketchy);
  EXPECT_EQ(s.objects[0].color, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_TRUE(s.objects[0].flat);
  EXPECT_EQ(s.camera.eye, glm::vec3(0, 0, 9));
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
      {R"({"mesh": {"procedural": "torus"}, "camera": {"fov_deg": "wide"}})", "bad.json: /camera/fov_deg: expected a number"},
      {R"({"mesh": {"procedural": "torus"}, "effects": ["contours", "oil"]})", "bad.json: /effects/1: unknown effect 'oil'"},
      {R"({"mesh": {"procedural": "torus"}, "params": {"edge.depth_scale": -1}})", "bad.json: /params/edge.depth_scale:"},
      {R"({"mesh": {"procedural": "torus"}, "params": {"edge.nope": 1}})", "bad.json: /params/edge.nope: unknown parameter"},
      {R"({"mesh": {"procedural": "donut"}})", "bad.json: /mesh: unknown procedural mesh 'donut'"},
      {R"({"objects": [{"mesh": "nowhere.obj"}]})", "bad.json: /objects/0/mesh:"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "transform": [1, 2]}]})", "bad.json: /objects/0/transform:"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "oil"}]})", "bad.json: /objects/0/style:"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [0, 10]})", "bad.json: /resolution/0: must be in 1..16384"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [10, 4294967396]})", "bad.json: /resolution/1: must be in"},
      {R"({"mesh": {"procedural": "torus"}, "resolution": [800.5, 10]})", "bad.json: /resolution: expected"},
      {R"({"mesh": 7})", "bad.json: /mesh: expected a mesh file path"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "color": [1, 2, 0]}]})", "bad.json: /objects/0/color/1: must be in [0, 1]"},
      {R"({"objects": [{"mesh": {"procedural": "torus"}, "flat": 1}]})", "bad.json: /objects/0/flat: expected true or false"},
      {R"({"objects": [{"mesh": {"procedural": "torus", "resolution": 99}}]})", "bad.json: /objects/0/mesh: procedural resolution"},
      {R"({"mesh": {"procedural": "torus"}, "camera": {"eye": [1, 2]}})", "bad.json: /camera/eye: expected an array of 3 numbers"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 1], "power": 2}]})", "bad.json: /lights/0/power: unknown key"},
      {R"({"mesh": {"procedural": "torus"}, "lights": [{"direction": [0, 0, 0]}]})", "bad.json: /lights/0/direction:"},
      {R"({"mesh": {"procedural": "torus"}, "seed": -3})", "bad.json: /seed:"},
      {R"({"mesh": {"procedural": "torus"}, "camera": {"near": 5, "far": 1}})", "bad.json: /camera: needs 0 < near < far"},
      {R"({"mesh": {"procedural": "torus"}, "objects": []})", "bad.json: /: give either"},
      {R"({})", "bad.json: /: give either"},
      {"{\n  \"mesh\": 1,,\n}", "bad.json: line 2, column 13"},
  };
  for (const auto& [json, expected] : cases) {
    std::string m = refusal(json);
    EXPECT_NE(m.find(expected), std::string::npos) << "scene " << json << "\n gave: " << m;
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
  if (!skipped.empty())
    GTEST_SKIP() << "shared models not here (../shared/models is absent): not loaded " << skipped;
}

// The JSON Schema names the same procedural kinds as the program; the effects, which the
// stages declare, it leaves to `plumbago effects` rather than keep a copy of the list.
TEST(SceneFile, SchemaListsTheProgramsKindsAndPointsToTheEffects) {
  std::ifstream in(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/scene.schema.json");
  nlohmann::json schema = nlohmann::json::parse(in);
  EXPECT_FALSE(schema["properties"]["effects"]["items"].contains("enum"));
  EXPECT_NE(schema["properties"]["effects"]["description"].get<std::string>().find("plumbago effects"), std::string::npos);
  EXPECT_EQ(schema["$defs"]["mesh"]["oneOf"][1]["properties"]["procedural"]["enum"].get<std::vector<std::string>>(),
            procedural_kinds());
}

}  // namespace
}  // namespace plumbago
