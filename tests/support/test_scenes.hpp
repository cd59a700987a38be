// Scenes the tests share: the built-in ones and the shared models (skipped when absent).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/core/params.hpp"
#include "common/mesh/mesh.hpp"
#include "common/pencil/distortion.hpp"
#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/gl/context.hpp"

namespace plumbago::testing {

inline std::string model_path(const std::string& name) { return std::string(PLUMBAGO_MODELS_DIR) + "/" + name; }
inline bool have_model(const std::string& name) { return std::filesystem::exists(model_path(name)); }

// A one-object scene of a shared model, camera and lights fitted by the scene parser.
inline Scene model_scene(const std::string& name, int width, int height) {
  std::string json =
      "{\"mesh\": \"" + name + "\", \"resolution\": [" + std::to_string(width) + ", " + std::to_string(height) + "]}";
  return parse_scene(json, "test:" + name, PLUMBAGO_MODELS_DIR);
}

inline Scene builtin_at(const std::string& name, int width, int height) {
  Scene s = builtin_scene(name);
  s.width = width;
  s.height = height;
  return s;
}

// `s` with every object drawn by stroke-based rendering (Kalnins et al. 2002): base coat and strokes.
inline Scene drawn_with_strokes(Scene s) {
  for (SceneObject& o : s.objects) o.style = Style::Strokes;
  s.effects = {"basecoat", "strokes"};
  return s;
}

// One object drawn with strokes, at the origin, seen from `eye` (its normals computed here).
inline Scene one_stroke_object(Mesh mesh, glm::vec3 eye, int width = 320, int height = 240) {
  compute_normals(mesh);
  Scene s;
  s.source = "test:one object";
  s.objects.push_back({std::make_shared<const Mesh>(std::move(mesh))});
  s.camera.eye = eye;
  s.camera.target = glm::vec3(0.0f);
  s.camera.near = 0.05f;
  s.width = width, s.height = height;
  return drawn_with_strokes(s);
}

// `s` with its cones (procedural) stripped of their (u, v): a mobile hatching group on one
// travels on an LSCM patch under it (common/strokes/mobile_hatching.hpp).
inline Scene cones_without_uvs(Scene s) {
  for (SceneObject& o : s.objects)
    if (o.mesh->name.find("cone") != std::string::npos) {
      Mesh stripped = *o.mesh;
      stripped.uvs.clear();
      o.mesh = std::make_shared<const Mesh>(std::move(stripped));
    }
  return s;
}

// A small square seen face-on and a torus, 240 x 180 (the blocks of 8 x 8 pixels do not fit
// its height): the GPU's skipped-pixel rectangles are exact around the square.
inline Scene square_and_torus(const std::string& background_pairs) {
  std::string json = R"({"objects": [{"mesh": {"procedural": "plane"},
      "transform": [0.3, 0, 0, 0,  0, 0.3, 0, 0,  0, 0, 0.3, 0,  0.9, 0.5, 0.2, 1]},
      {"mesh": {"procedural": "torus"}, "transform": [0.5, 0, 0, 0,  0, 0.5, 0, 0,  0, 0, 0.5, 0,  -0.6, -0.4, 0, 1]}],
    "camera": {"view_direction": [0, 0, 1]}, "effects": ["contours", "interior"], "resolution": [240, 180],
    "params": {"edge.background_pairs": ")" +
                     background_pairs + R"("}})";
  return parse_scene(json, "test:skipped", ".");
}

// The procedural stroke scenes whose silhouettes the coherence tests follow (Kalnins et al.
// 2003), and a scene of scenes/ on an orbit of `frames` frames 4 degrees apart.
inline const char* const kOrbitScenes[] = {"torus_strokes.json", "snowman_strokes.json", "cup_strokes.json"};
inline Scene orbit_scene(const std::string& name, int frames) {
  Scene s = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/" + name);
  s.animation = Animation{.kind = Animation::Kind::Orbit, .amount = -4.0 * (frames - 1), .frames = frames};
  return s;
}

// Multiple-contour parameters without the contour texture: each copy lays down alpha d'.
inline ContourParams untextured_contours(int copies, int grid_cell) {
  ParamSet set;
  set.set("contour.copies", double(copies));
  set.set("contour.texture_strength", 0.0);
  set.set("contour.grid_cell", double(grid_cell));
  return set.get<ContourParams>();
}

// Any GL error a test causes fails that test.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { gpu::Context::get(); }
  void TearDown() override {
    EXPECT_NO_THROW(gpu::Context::get().check_errors(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  }
};

}  // namespace plumbago::testing

// Skips the test, saying why, when the shared model is absent.
#define PLUMBAGO_REQUIRE_MODEL(name)          \
  if (!::plumbago::testing::have_model(name)) \
  GTEST_SKIP() << "shared model not here: ../shared/models/" << (name) << " is absent"
