#include "common/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace plumbago {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fov_deg), aspect, near, far);
}

glm::vec3 Camera::forward() const { return glm::normalize(target - eye); }

PrimaryRays::PrimaryRays(const Camera& c, int width, int height)
    : camera_to_world_(glm::inverse(c.view())),
      tan_half_(std::tan(glm::radians(c.fov_deg) * 0.5f)),
      aspect_(float(width) / float(height)),
      width_(width),
      height_(height) {}

glm::vec3 PrimaryRays::direction(float px, float py) const {
  float x = (2.0f * px / float(width_) - 1.0f) * tan_half_ * aspect_;
  float y = (2.0f * py / float(height_) - 1.0f) * tan_half_;
  return glm::normalize(camera_to_world_ * glm::vec3(x, y, -1.0f));
}

Camera fit_camera(glm::vec3 center, float radius, glm::vec3 direction, float fov_deg) {
  Camera c;
  c.fov_deg = fov_deg;
  float distance = radius / std::sin(glm::radians(fov_deg) * 0.5f) * 1.05f;
  c.target = center;
  c.eye = center + glm::normalize(direction) * distance;
  glm::vec3 d = glm::normalize(direction);
  c.up = std::abs(d.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  c.near = std::max(distance - radius * 1.5f, distance * 0.01f);
  c.far = distance + radius * 1.5f;
  return c;
}

void fit_planes(Camera& c, glm::vec3 center, float radius) {
  float d = glm::dot(center - c.eye, c.forward());
  c.far = std::max(d + radius * 1.5f, radius * 0.1f);
  c.near = std::max(d - radius * 1.5f, c.far * 1e-3f);
}

}  // namespace plumbago
