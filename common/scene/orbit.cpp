#include "common/scene/orbit.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace plumbago {

namespace {

glm::vec3 turn(const glm::mat4& rotation, glm::vec3 point, glm::vec3 pivot) {
  return pivot + glm::vec3(rotation * glm::vec4(point - pivot, 0.0f));
}

// Angle in degrees between the viewing direction and the up vector.
float polar_deg(glm::vec3 forward, glm::vec3 up) {
  return glm::degrees(std::acos(glm::clamp(glm::dot(forward, glm::normalize(up)), -1.0f, 1.0f)));
}

}  // namespace

OrbitCamera::OrbitCamera(const Camera& home, glm::vec3 center, float radius)
    : home_(home), camera_(home), center_(center), pivot_(center), radius_(radius) {}

void OrbitCamera::orbit(float yaw_deg, float pitch_deg) {
  glm::vec3 forward = camera_.forward();
  float polar = polar_deg(forward, camera_.up);
  // Pitching up (positive) turns the view down toward -up: the polar angle grows.
  pitch_deg = glm::clamp(pitch_deg, 1.0f - polar, 179.0f - polar);
  glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), glm::radians(yaw_deg), glm::normalize(camera_.up)) *
                       glm::rotate(glm::mat4(1.0f), glm::radians(-pitch_deg), right);
  camera_.eye = turn(rotation, camera_.eye, pivot_);
  camera_.target = turn(rotation, camera_.target, pivot_);
  refit();
}

void OrbitCamera::pan(glm::vec2 fraction) {
  glm::vec3 forward = camera_.forward();
  glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  glm::vec3 up = glm::cross(right, forward);
  float depth = std::max(glm::dot(pivot_ - camera_.eye, forward), camera_.near);
  float height = 2.0f * depth * std::tan(glm::radians(camera_.fov_deg) * 0.5f);
  glm::vec3 move = -(right * fraction.x + up * fraction.y) * height;
  camera_.eye += move;
  camera_.target += move;
  pivot_ += move;
  refit();
}

void OrbitCamera::zoom(float factor) {
  // No closer than a thousandth of the scene's radius: the view direction stays defined.
  factor = std::max(factor, radius_ * 1e-3f / glm::length(camera_.target - camera_.eye));
  camera_.eye = pivot_ + (camera_.eye - pivot_) * factor;
  camera_.target = pivot_ + (camera_.target - pivot_) * factor;
  refit();
}

void OrbitCamera::frame() {
  Camera fitted = fit_camera(center_, radius_, camera_.eye - camera_.target, camera_.fov_deg);
  if (polar_deg(fitted.forward(), camera_.up) > 1.0f && polar_deg(fitted.forward(), camera_.up) < 179.0f)
    fitted.up = camera_.up;
  camera_ = fitted;
  pivot_ = center_;
}

void OrbitCamera::reset() {
  camera_ = home_;
  pivot_ = center_;
}

}  // namespace plumbago
