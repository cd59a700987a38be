// Saving a scene (common/scene/scene_save.cpp, what `plumbago view` saves) and keeping its
// effects consistent with its object styles (match_effects_to_styles).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/core/passes.hpp"
#include "common/scene/scene.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

using testing::TempDir;

// What the viewer changes in a scene: camera, lights, every kind of parameter, a style.
void edit(Scene& s) {
  s.camera.eye = glm::vec3(0.1f, 4.3f, 7.7f);
  s.camera.target = glm::vec3(0.3f, 0.2f, 0.1f);
  s.camera.fov_deg = 33.3f;
  s.camera.near = 0.123f;
  s.camera.far = 45.6f;
  s.lights = default_lights(s.camera);
  s.params.set("edge.depth_scale", 12.345678901);
  s.params.set("contour.copies", 2.0);
  s.params.set("edge.normals", "face");
  s.params.set("basecoat.abs_n_dot_l", "true");
  s.objects.back().style = Style::Sketchy;
  match_effects_to_styles(s);
}

void expect_same(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.camera.eye, b.camera.eye);
  EXPECT_EQ(a.camera.target, b.camera.target);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fov_deg, b.camera.fov_deg);
  EXPECT_EQ(a.camera.near, b.camera.near);
  EXPECT_EQ(a.camera.far, b.camera.far);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].direction, b.lights[i].direction);
    EXPECT_EQ(a.lights[i].intensity, b.lights[i].intensity);
  }
  EXPECT_EQ(a.params.overrides(), b.params.overrides());
  EXPECT_EQ(a.effects, b.effects);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.seed, b.seed);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].style, b.objects[i].style) << i;
    EXPECT_EQ(a.objects[i].mesh->positions, b.objects[i].mesh->positions) << i;
    EXPECT_EQ(a.objects[i].transform, b.objects[i].transform) << i;
  }
}

TEST(SceneSave, ReloadsToTheSameSceneFromAnotherFolder) {
  TempDir tmp;
  std::filesystem::create_directories(tmp.path("a"));
  std::filesystem::create_directories(tmp.path("b/c"));
  tmp.write("a/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::string path = tmp.write("a/s.json", R"({
    "objects": [{"mesh": "tri.obj", "color": [0.5, 0.25, 1]},
                {"mesh": {"procedural": "torus"}, "transform": [2,0,0,0, 0,2,0,0, 0,0,2,0, 1,2,3,1]},
                {"mesh": {"file": "tri.obj", "decimate_to": 4}}],
    "resolution": [320, 200], "seed": 42, "params": {"paper.mu_p": 0.1}})");
  Scene s = load_scene(path);
  edit(s);
  save_scene(s, tmp.path("b/c/saved.json"));
  Scene back = load_scene(tmp.path("b/c/saved.json"));
  expect_same(s, back);
  EXPECT_EQ(back.objects[0].color, glm::vec3(0.5f, 0.25f, 1.0f)) << "what the viewer does not edit stays";
  std::ifstream in(tmp.path("b/c/saved.json"));
  nlohmann::json saved = nlohmann::json::parse(in);
  EXPECT_EQ(saved["objects"][0]["mesh"], "../../a/tri.obj") << "relative to the new folder";
  EXPECT_EQ(saved["objects"][2]["mesh"]["file"], "../../a/tri.obj") << "a decimated file's too";
  EXPECT_EQ(saved["objects"][2]["mesh"]["decimate_to"], 4);
}

TEST(SceneSave, BuiltinSceneSavesItsProceduralMesh) {
  TempDir tmp;
  Scene s = builtin_scene("cad");
  edit(s);
  save_scene(s, tmp.path("cad.json"));
  expect_same(s, load_scene(tmp.path("cad.json")));
}

TEST(SceneSave, FailureLeavesNoFile) {
  TempDir tmp;
  Scene s = builtin_scene("torus");
  EXPECT_ANY_THROW(save_scene(s, tmp.path("absent/s.json")));
  s.source =
      tmp.write("changed.json", R"({"objects": [{"mesh": {"procedural": "torus"}}, {"mesh": {"procedural": "cad"}}]})");
  EXPECT_THROW(save_scene(s, tmp.path("s.json")), SceneError) << "the file's objects no longer match the scene's";
  EXPECT_FALSE(std::filesystem::exists(tmp.path("s.json")));
}

TEST(SceneEffects, FollowTheObjectStyles) {
  Scene s = builtin_scene("torus");
  ASSERT_EQ(s.effects, std::vector<std::string>{"contours"});
  s.objects[0].style = Style::Sketchy;
  match_effects_to_styles(s);
  EXPECT_EQ(s.effects, (std::vector<std::string>{"contours", "sketchy"})) << "sketchy is on by itself";
  s.objects[0].style = Style::Strokes;
  match_effects_to_styles(s);
  EXPECT_EQ(s.effects, (std::vector<std::string>{"contours", "strokes"})) << "no sketchy object left";
  s.effects.push_back("basecoat");
  s.objects[0].style = Style::Pencil;
  match_effects_to_styles(s);
  EXPECT_EQ(s.effects, std::vector<std::string>{"contours"}) << "the base coat coats stroke objects only";
}

// The effects that go with a style are the ones the stages declare so (EffectDef::styled).
TEST(SceneEffects, StyleEffectsAreTheStyledOnes) {
  for (const EffectDef& e : effect_table()) EXPECT_EQ(style_effect(e.name) != nullptr, e.styled) << e.name;
  ASSERT_NE(style_effect("basecoat"), nullptr);
  EXPECT_EQ(style_effect("basecoat")->style, Style::Strokes);
  EXPECT_FALSE(style_effect("basecoat")->automatic);
}

}  // namespace
}  // namespace plumbago
