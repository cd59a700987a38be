// Texture rotation (Lee et al. 2006, §5.3): corner angles raster vs ray, and the hard cases.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "common/curvature/texture_rotation.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// The corner angles of Lee et al. 2006, §5.3 are G-buffer channels: raster vs ray on the same curvature,
// where both backends see the same triangle away from depth discontinuities.
const std::vector<std::string> kGBufferWithAngles = {"gbuffer.normal",   "gbuffer.face_normal", "gbuffer.depth",
                                                     "gbuffer.bary",     "gbuffer.gouraud",     "gbuffer.theta_min",
                                                     "gbuffer.theta_max"};

class TextureRotationParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(TextureRotationParity, CornerAnglesAgree) {
  Scene scene = testing::builtin_at(GetParam(), 320, 240);
  scene.effects = {"contours", "interior"};
  auto results = run_parity(scene, {"gbuffer"});
  ASSERT_EQ(testing::names_of(results), kGBufferWithAngles);
  for (const StageParity& r : results) {
    if (r.name.find("theta") == std::string::npos) continue;
    std::printf("[%s %s] %s\n", r.name.c_str(), GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_GT(r.diff.compared, 1000u);
    EXPECT_TRUE(r.pass) << r.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, TextureRotationParity, ::testing::Values("torus", "cad", "sphere"));

// Two objects: each reads its own triangles' angle records (gpu/scene/gbuffer.hpp TriangleAngles,
// the second object's after the first's), in the G-buffer's angle channels and in the
// pencil interior.
TEST_F(TextureRotationParity, EachOfTwoObjectsReadsItsOwnTriangles) {
  Scene scene = parse_scene(R"({"objects": [{"mesh": {"procedural": "cad"}},
                                           {"mesh": {"procedural": "sphere"},
                                            "transform": [0.5,0,0,0, 0,0.5,0,0, 0,0,0.5,0, 1.4,0.2,0.6,1]}],
                               "resolution": [320, 240], "effects": ["contours", "interior", "crosshatch"]})",
                            "test:two objects", ".");
  auto results = run_parity(scene, {"gbuffer", "pencil_interior"});
  std::vector<std::string> expected = kGBufferWithAngles;
  expected.push_back("interior_intensity.intensity in interior_intensity+pencil_interior");
  expected.push_back("pencil_interior.interior_darkness in interior_intensity+pencil_interior");
  ASSERT_EQ(testing::names_of(results), expected);
  for (const StageParity& r : results) {
    if (r.name.find("theta") == std::string::npos && r.name.find("pencil_interior.") == std::string::npos) continue;
    std::printf("[%s two objects] %s\n", r.name.c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_GT(r.diff.compared, 1000u);
    EXPECT_TRUE(r.pass) << r.name;
  }
}

ProjectionInfo looking_down_z() {
  glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
  return {glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 100.0f) * view, 400, 400, std::tan(glm::radians(20.0f))};
}

TEST(TextureRotation, DirectionsAcrossTheViewKeepTheirAngle) {
  ProjectionInfo proj = looking_down_z();
  EXPECT_NEAR(stroke_angle(proj, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.05f), 0.0f, 1e-5f);
  EXPECT_NEAR(stroke_angle(proj, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0.05f), 1.5707963f, 1e-5f);
  EXPECT_NEAR(stroke_angle(proj, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0.05f), 0.7853982f, 1e-5f);
}

// Straight down a cylinder's axis: the direction is parallel to the view ray.
TEST(TextureRotation, ADirectionAlongTheViewRayFallsBackWithoutNaN) {
  ProjectionInfo proj = looking_down_z();
  EXPECT_NEAR(stroke_angle(proj, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0.05f), 1.5707963f + 1.5707963f, 1e-5f);
  float both_short = stroke_angle(proj, {0, 0, 0}, {0, 0, 1}, {0, 0, -1}, 0.05f);
  EXPECT_EQ(both_short, 0.0f);
  EXPECT_FALSE(window_angle(proj, {0, 0, 0}, {0, 0, 0}, 0.05f).reliable);                  // zero direction
  EXPECT_TRUE(std::isfinite(stroke_angle(proj, {0, 0, 5}, {1, 0, 0}, {0, 1, 0}, 0.05f)));  // at the eye
}

}  // namespace
}  // namespace plumbago
