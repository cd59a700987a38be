// The viewer's camera moves (common/scene/orbit.hpp): orbit, pan, zoom, frame, reset.
#include <gtest/gtest.h>

#include <cmath>

#include "common/scene/orbit.hpp"

namespace plumbago {
namespace {

const glm::vec3 kCenter(1, 2, 3);
constexpr float kRadius = 2;

OrbitCamera test_orbit() { return OrbitCamera(fit_camera(kCenter, kRadius, glm::vec3(0, 0, 1), 40), kCenter, kRadius); }

float polar_deg(const Camera& c) { return glm::degrees(std::acos(glm::dot(c.forward(), glm::normalize(c.up)))); }

// The near and far planes bracket the bounding sphere.
void expect_brackets(const Camera& c) {
  float d = glm::dot(kCenter - c.eye, c.forward());
  EXPECT_LT(c.near, d - kRadius);
  EXPECT_GT(c.far, d + kRadius);
  EXPECT_GT(c.near, 0);
}

TEST(Orbit, TurnsAboutThePivotAtItsDistance) {
  OrbitCamera o = test_orbit();
  float distance = glm::length(o.camera().eye - kCenter);
  o.orbit(90, 0);
  EXPECT_NEAR(glm::length(o.camera().eye - kCenter), distance, 1e-4f);
  EXPECT_NEAR(o.camera().eye.x - kCenter.x, distance, 1e-4f) << "a quarter turn about +y takes +z to +x";
  EXPECT_NEAR(glm::length(o.camera().target - kCenter), 0, 1e-4f);
  o.orbit(0, 30);
  EXPECT_GT(o.camera().eye.y, kCenter.y) << "pitching up raises the eye";
  EXPECT_NEAR(polar_deg(o.camera()), 120, 1e-2f);
  expect_brackets(o.camera());
}

TEST(Orbit, StopsShortOfThePoles) {
  OrbitCamera o = test_orbit();
  o.orbit(0, 500);
  EXPECT_NEAR(polar_deg(o.camera()), 179, 1e-2f);
  o.orbit(0, -500);
  EXPECT_NEAR(polar_deg(o.camera()), 1, 1e-2f);
  EXPECT_FALSE(std::isnan(o.camera().eye.x));
}

TEST(Orbit, PanMovesEyeTargetAndPivotTogether) {
  OrbitCamera o = test_orbit();
  glm::vec3 eye = o.camera().eye;
  o.pan(glm::vec2(0.5f, 0));
  glm::vec3 moved = o.camera().eye - eye;
  float depth = glm::length(eye - kCenter);
  float height = 2 * depth * std::tan(glm::radians(20.0f));
  EXPECT_NEAR(moved.x, -0.5f * height, 1e-4f) << "the scene follows the cursor to the right";
  EXPECT_NEAR(glm::length(o.pivot() - kCenter - moved), 0, 1e-5f);
  EXPECT_NEAR(glm::length(o.camera().target - kCenter - moved), 0, 1e-5f);
}

TEST(Orbit, ZoomScalesTheDistanceAndNeverReachesThePivot) {
  OrbitCamera o = test_orbit();
  float distance = glm::length(o.camera().eye - kCenter);
  o.zoom(0.5f);
  EXPECT_NEAR(glm::length(o.camera().eye - kCenter), distance * 0.5f, 1e-4f);
  for (int i = 0; i < 200; ++i) o.zoom(0.5f);
  EXPECT_GE(glm::length(o.camera().target - o.camera().eye), kRadius * 1e-3f * 0.99f);
  EXPECT_GT(o.camera().near, 0);
  EXPECT_GT(o.camera().far, o.camera().near);
}

TEST(Orbit, FrameAndResetGoBack) {
  OrbitCamera o = test_orbit();
  Camera home = o.camera();
  o.orbit(40, 10);
  o.pan(glm::vec2(0.3f, -0.2f));
  o.zoom(3);
  o.frame();
  EXPECT_NEAR(glm::length(o.camera().target - kCenter), 0, 1e-5f);
  EXPECT_NEAR(glm::length(o.camera().eye - kCenter), glm::length(home.eye - kCenter), 1e-3f)
      << "as far as a fitted camera";
  EXPECT_EQ(o.pivot(), kCenter);
  o.reset();
  EXPECT_EQ(o.camera().eye, home.eye);
  EXPECT_EQ(o.camera().target, home.target);
  EXPECT_EQ(o.camera().near, home.near);
}

}  // namespace
}  // namespace plumbago
