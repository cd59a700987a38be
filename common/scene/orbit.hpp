// Interactive camera moves (plumbago view): orbit about a pivot, pan across the view,
// zoom toward the pivot, frame the scene, back to the scene's own camera. After every
// move the near and far planes bracket the scene's bounding sphere again.
#pragma once

#include <glm/glm.hpp>

#include "common/scene/camera.hpp"

namespace plumbago {

class OrbitCamera {
 public:
  // `home`: the scene's camera; the pivot starts at the bounding sphere's center.
  OrbitCamera(const Camera& home, glm::vec3 center, float radius);

  const Camera& camera() const { return camera_; }
  glm::vec3 pivot() const { return pivot_; }

  // Turns eye and target about the pivot: `yaw_deg` about the camera's up vector (a
  // turntable), `pitch_deg` about its right axis, stopping a degree short of the poles.
  void orbit(float yaw_deg, float pitch_deg);
  // Slides eye, target and pivot across the view by `fraction` of the view's height at
  // the pivot's depth (x right, y up): the scene follows the cursor.
  void pan(glm::vec2 fraction);
  // Scales the eye's and target's distances to the pivot by `factor` (< 1: closer).
  void zoom(float factor);
  // Looks at the bounding sphere's center from the current direction, the sphere filling
  // the view (as a scene's fitted camera does); the pivot goes back to the center.
  void frame();
  // The scene's own camera and the center as the pivot.
  void reset();

 private:
  void refit() { fit_planes(camera_, center_, radius_); }
  Camera home_, camera_;
  glm::vec3 center_, pivot_;
  float radius_;
};

}  // namespace plumbago
