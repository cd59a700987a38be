#include "common/scene/animation.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "common/scene/scene.hpp"

namespace plumbago {

Camera camera_at(const Camera& c, const Animation& a, int frame, glm::vec3 center, float radius) {
  if (frame == 0) return c;
  Camera out = c;
  double t = a.fraction(frame);
  glm::dvec3 eye = c.eye, target = c.target;
  if (a.kind == Animation::Kind::Orbit) {
    glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(a.amount * t), glm::normalize(glm::dvec3(c.up)));
    out.eye = glm::vec3(target + glm::dvec3(turn * glm::dvec4(eye - target, 0.0)));
  } else {
    out.eye = glm::vec3(eye + glm::normalize(target - eye) * (a.amount * t));
    fit_planes(out, center, radius);
  }
  return out;
}

namespace {

// Frame 0's camera and the bounding sphere a dolly fits its planes to.
struct PathStart {
  Camera camera;
  glm::vec3 center;
  float radius;
};
PathStart path_start(const Scene& scene) {
  PathStart out{scene.frame > 0 ? scene.path_start : scene.camera, {}, 0};
  scene_bounds(scene, out.center, out.radius);
  return out;
}

}  // namespace

Camera frame_camera(const Scene& scene, int frame) {
  if (!scene.animation) return scene.camera;
  PathStart start = path_start(scene);
  return camera_at(start.camera, *scene.animation, frame, start.center, start.radius);
}

std::vector<Camera> path_cameras(const Scene& scene) {
  if (!scene.animation) return {scene.camera};
  PathStart start = path_start(scene);
  std::vector<Camera> out;
  for (int k = 0; k <= scene.frame; ++k)
    out.push_back(camera_at(start.camera, *scene.animation, k, start.center, start.radius));
  return out;
}

Scene scene_at_frame(const Scene& scene, int frame) {
  Scene s = scene;
  move_along_path(s, frame);
  return s;
}

void move_along_path(Scene& s, int frame) {
  if (!s.animation) return;
  const Camera camera = frame_camera(s, frame);  // from the path's start as `s` has it
  if (s.frame == 0) s.path_start = s.camera;
  s.camera = camera;
  s.frame = frame;
  if (s.lights_follow_camera) s.lights = default_lights(s.camera);
}

void take_view(Scene& to, const Scene& from) {
  to.camera = from.camera;
  to.lights = from.lights;
  to.frame = from.frame;
  to.path_start = from.path_start;
}

}  // namespace plumbago
