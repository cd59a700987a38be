// A renderer moved along a camera path (gpu::Renderer::camera_moved) draws each frame as a renderer
// made at that frame does: the same image, bit for bit, and the same stroke counts. Frames are
// visited out of order (first, last, middle, first) so that the objects' window rectangle, the
// lights that follow the camera and the stroke buffers' sizes all move far between frames.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/core/pipeline.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class CameraMove : public testing::GlTest {};

Scene repository_scene(const std::string& name, int width, int height) {
  Scene s = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/" + name);
  s.width = width;
  s.height = height;
  return s;
}

// `s` orbiting `degrees` over `frames`, with its lights following the camera.
Scene orbiting(Scene s, double degrees, int frames) {
  s.animation = Animation{Animation::Kind::Orbit, degrees, frames};
  s.lights_follow_camera = true;
  s.lights = default_lights(s.camera);
  return s;
}

void expect_moves_like_fresh_renderers(const Scene& path, const std::string& what) {
  const int last = path.animation->frames - 1;
  Scene at = scene_at_frame(path, 0);
  gpu::Renderer moved(at);
  for (int k : {0, last, last / 2, 0}) {
    SCOPED_TRACE(what + ", frame " + std::to_string(k));
    Frame fresh = gpu::Renderer(scene_at_frame(path, k)).render();
    move_along_path(at, k);
    moved.camera_moved();
    Frame timed;
    moved.render_frame(timed);  // a lean frame, which sizes the stroke buffers after the move
    EXPECT_EQ(moved.color().data, fresh.color.data) << "the lean frame";
    if (!fresh.counts.empty()) {
      EXPECT_GT(timed.readback_bytes, 0u) << "the stroke buffers sized again";
    }
    moved.camera_moved();
    Frame read = moved.render();
    EXPECT_EQ(read.color.data, fresh.color.data);
    EXPECT_EQ(read.counts, fresh.counts);
  }
}

TEST_F(CameraMove, PencilFramesWithLightsFollowingTheCamera) {
  expect_moves_like_fresh_renderers(repository_scene("cad_orbit.json", 160, 120), "cad_orbit");
}

TEST_F(CameraMove, SketchyFramesWithLightsFollowingTheCamera) {
  expect_moves_like_fresh_renderers(orbiting(repository_scene("sketchy_mixed.json", 160, 120), 120, 5),
                                    "sketchy_mixed");
}

TEST_F(CameraMove, StrokeFramesWithBaseCoatAndLightsFollowingTheCamera) {
  Scene s = orbiting(testing::drawn_with_strokes(testing::builtin_at("torus", 160, 120)), 90, 5);
  expect_moves_like_fresh_renderers(s, "torus in strokes");
}

// From a few pixels across to most of the window: the lines' lengths, samples and runs change.
TEST_F(CameraMove, StrokeFramesAlongADollyIn) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("torus", 200, 150));
  s.camera.eye = s.camera.target + 4.0f * (s.camera.eye - s.camera.target);  // far: a few pixels across
  s.camera.far *= 4.0f;
  s.animation = Animation{Animation::Kind::Dolly, 0.7 * glm::distance(s.camera.eye, s.camera.target), 3};
  expect_moves_like_fresh_renderers(s, "torus dolly");
}

TEST_F(CameraMove, MobileHatchingAndDecalsStayOnTheSurface) {
  expect_moves_like_fresh_renderers(repository_scene("snowman_mobile.json", 200, 150), "snowman_mobile");
}

}  // namespace
}  // namespace plumbago
