// The shower-door measure (experiments/shower_door): the coherence score on fields whose
// motion is known, the surface motion on a real render, and the paper's claim (Nienhaus &
// Döllner 2004 §4.3) that the object style sticks to the surface where default does not.
#include <gtest/gtest.h>

#include <cmath>

#include "common/scene/scene.hpp"
#include "experiments/shower_door/coherence.hpp"
#include "experiments/shower_door/sketch_frames.hpp"
#include "experiments/shower_door/surface_motion.hpp"

namespace plumbago {
namespace {

using namespace shower_door;

// A smooth 2-channel pattern of window position q.
glm::vec2 pattern(glm::vec2 q) { return {std::sin(q.x / 9.0f) + std::cos(q.y / 13.0f), std::sin((q.x + q.y) / 11.0f)}; }

Image field_of(int w, int h, glm::vec2 shift) {
  Image f(w, h, 2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      glm::vec2 v = pattern(glm::vec2(x + 0.5f, y + 0.5f) + shift);
      f.at(x, y, 0) = v.x, f.at(x, y, 1) = v.y;
    }
  return f;
}

// Every pixel's surface was at p + (2.5, -1.5) in the previous frame, away from the border.
Image uniform_motion(int w, int h, glm::vec2 d) {
  Image m(w, h, 3);
  for (int y = 4; y < h - 4; ++y)
    for (int x = 4; x < w - 4; ++x) m.at(x, y, 0) = x + 0.5f + d.x, m.at(x, y, 1) = y + 0.5f + d.y, m.at(x, y, 2) = 1;
  return m;
}

TEST(ShowerDoor, PatternCarriedByTheSurfaceScoresOne) {
  glm::vec2 d(2.5f, -1.5f);
  Image motion = uniform_motion(64, 48, d);
  Image prev = field_of(64, 48, {0, 0}), next = field_of(64, 48, d);  // next(p) = prev(p + d)
  Residuals r = residuals(prev, next, motion, Sampling::Bilinear);
  EXPECT_EQ(r.pixels, size_t(56 * 40));
  EXPECT_GT(r.fixed, 0.1);
  EXPECT_LT(r.attached, 0.02 * r.fixed);  // only bilinear interpolation's error
  EXPECT_GT(r.coherence(), 0.98);
}

TEST(ShowerDoor, PatternFixedToTheScreenScoresZero) {
  Image motion = uniform_motion(64, 48, {2.5f, -1.5f});
  Image f = field_of(64, 48, {0, 0});
  Residuals r = residuals(f, f, motion, Sampling::Nearest);
  EXPECT_GT(r.attached, 0.1);
  EXPECT_EQ(r.fixed, 0.0);
  EXPECT_EQ(r.coherence(), 0.0);
}

TEST(ShowerDoor, HalfwayPatternScoresInBetween) {
  glm::vec2 d(4.0f, 0.0f);
  Image motion = uniform_motion(64, 48, d);
  Image prev = field_of(64, 48, {0, 0}), next = field_of(64, 48, 0.5f * d);  // moved half as far as the surface
  double c = residuals(prev, next, motion, Sampling::Nearest).coherence();
  EXPECT_GT(c, 0.3);
  EXPECT_LT(c, 0.7);
}

TEST(ShowerDoor, NoValidPixelOrNoChangeIsNaN) {
  Image f = field_of(16, 16, {0, 0});
  EXPECT_TRUE(std::isnan(residuals(f, f, Image(16, 16, 3), Sampling::Bilinear).coherence()));
  Image constant(16, 16, 2, 0.25f);
  EXPECT_TRUE(
      std::isnan(residuals(constant, constant, uniform_motion(16, 16, {2, 0}), Sampling::Bilinear).coherence()));
}

Scene sketchy_torus(int size) {
  std::string json = R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "sketchy"}], "resolution": [)" +
                     std::to_string(size) + ", " + std::to_string(size) + "]}";
  return parse_scene(json, "test:shower_door", ".");
}

TEST(ShowerDoor, OrbitTurnsTheEyeAboutTheTarget) {
  Camera c;
  c.eye = {0, 1, 5}, c.target = {0, 1, 0}, c.up = {0, 1, 0};
  Camera turned = orbit(c, 90);
  EXPECT_NEAR(turned.eye.x, 5, 1e-5);
  EXPECT_NEAR(turned.eye.y, 1, 1e-5);
  EXPECT_NEAR(turned.eye.z, 0, 1e-5);
}

// The surface's own world position is attached to it by definition: warped by the
// measured motion it must score ~1, and the motion must be a few pixels.
TEST(ShowerDoor, SurfaceMotionCarriesTheSurfacesOwnPositions) {
  Scene scene = sketchy_torus(160);
  std::vector<WorldObject> world = world_geometry(scene);
  Camera a = orbit(scene.camera, 0), b = orbit(scene.camera, 2);
  Image pa = surface_points(world, trace_view(scene, a).gbuffer),
        pb = surface_points(world, trace_view(scene, b).gbuffer);
  Image motion = surface_motion(a, pa, pb);
  Residuals r = residuals(pa, pb, motion, Sampling::Bilinear);
  std::printf("[shower door, torus 160x160, 2 deg] %zu moving pixels, position coherence %.4f\n", r.pixels,
              r.coherence());
  EXPECT_GT(r.pixels, 1000u);
  EXPECT_GT(r.coherence(), 0.95);
  // project() agrees with the tracer: a pixel's own point projects back onto its center.
  for (int y = 0; y < 160; y += 7)
    for (int x = 0; x < 160; x += 7)
      if (pb.at(x, y, 3) != 0) {
        glm::vec3 q = project(b, 160, 160, glm::vec3(pb.at(x, y, 0), pb.at(x, y, 1), pb.at(x, y, 2)));
        EXPECT_NEAR(q.x, x + 0.5f, 1e-2);
        EXPECT_NEAR(q.y, y + 0.5f, 1e-2);
      }
}

// The paper's claim (§4.3) on a small torus orbit: object style's perturbation follows
// the surface, default's stays on the screen.
TEST(ShowerDoor, ObjectStyleFollowsTheSurfaceAndDefaultDoesNot) {
  Scene scene = sketchy_torus(128);
  std::vector<WorldObject> world = world_geometry(scene);
  Mode object = make_mode(scene, "object"), standard = make_mode(scene, "default");
  Camera a = orbit(scene.camera, 0), b = orbit(scene.camera, 2);
  View va = trace_view(scene, a), vb = trace_view(scene, b);
  Image motion = surface_motion(a, surface_points(world, va.gbuffer), surface_points(world, vb.gbuffer));
  double c_object =
      residuals(render_mode(object, va).field, render_mode(object, vb).field, motion, Sampling::Bilinear).coherence();
  double c_default =
      residuals(render_mode(standard, va).field, render_mode(standard, vb).field, motion, Sampling::Bilinear)
          .coherence();
  std::printf("[shower door, torus 128x128, 2 deg] coherence object %.3f, default %.3f\n", c_object, c_default);
  EXPECT_GT(c_object, 0.6);
  EXPECT_LT(c_default, 0.1);
}

}  // namespace
}  // namespace plumbago
