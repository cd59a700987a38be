// The pinhole camera of SPEC §0: right-handed view space looking down -Z, vertical field
// of view, pixel centers at (i + 0.5, j + 0.5) from the bottom-left corner.
#pragma once

#include <glm/glm.hpp>

namespace plumbago {

struct Camera {
  glm::vec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  float fov_deg = 40;
  float near = 0.1f, far = 100;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;  // OpenGL clip space, depth in [-1, 1]
  // Unit world-space viewing direction (target - eye).
  glm::vec3 forward() const;
};

// Primary-ray directions of one camera and image size (SPEC 0), the camera basis
// computed once.
class PrimaryRays {
 public:
  PrimaryRays(const Camera& camera, int width, int height);
  // Unit world-space direction through window point (px, py); pixel centers sit at
  // integer + 0.5, from the bottom-left corner.
  glm::vec3 direction(float px, float py) const;

 private:
  glm::mat3 camera_to_world_;
  float tan_half_, aspect_;
  int width_, height_;
};

// A camera fitted to a bounding sphere: looks at its center from `direction`, with the
// sphere filling the view and near/far planes bracketing it.
Camera fit_camera(glm::vec3 center, float radius, glm::vec3 direction, float fov_deg);
// Sets the near and far planes to bracket a bounding sphere seen from the camera.
void fit_planes(Camera& c, glm::vec3 center, float radius);

}  // namespace plumbago
