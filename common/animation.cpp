#include "common/animation.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "common/scene.hpp"

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

Scene scene_at_frame(const Scene& scene, int frame) {
  Scene s = scene;
  if (!scene.animation) return s;
  glm::vec3 center;
  float radius;
  scene_bounds(scene, center, radius);
  s.camera = camera_at(scene.camera, *scene.animation, frame, center, radius);
  if (s.lights_follow_camera) s.lights = default_lights(s.camera);
  return s;
}

}  // namespace plumbago
