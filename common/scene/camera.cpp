#include "common/scene/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

namespace plumbago {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const { return glm::perspective(glm::radians(fov_deg), aspect, near, far); }

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

std::string format_number(double v) {
  if (std::isnan(v)) return "not a number";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string format_point(glm::dvec3 p) {
  std::string out = "(";
  out.append(format_number(p.x)).append(", ").append(format_number(p.y)).append(", ").append(format_number(p.z));
  return out.append(")");
}

namespace {

std::optional<CameraFault> fov_fault(const Camera& c, double aspect) {
  if (!(c.fov_deg > 0 && c.fov_deg < 180)) return CameraFault{"fov_deg", "must be in (0, 180) degrees"};
  double tan_half = std::tan(glm::radians(double(c.fov_deg)) * 0.5);
  double narrower = glm::degrees(2 * std::atan(tan_half * std::min(1.0, aspect)));
  if (narrower < kMinFovDeg)
    return CameraFault{"fov_deg", "gives a field of view of " + format_number(narrower) + " degrees" +
                                      (aspect < 1 ? " across the image" : "") + ", under the " +
                                      format_number(kMinFovDeg) + " that float can render"};
  return std::nullopt;
}

std::optional<CameraFault> position_fault(const Camera& c, glm::dvec3 origin) {
  for (auto [key, p] : {std::pair{"eye", glm::dvec3(c.eye) + origin}, {"target", glm::dvec3(c.target) + origin}})
    if (!glm::all(glm::lessThanEqual(glm::abs(p), glm::dvec3(kMaxCoordinate))))
      return CameraFault{key, "lies at " + format_point(p) + ", beyond ±" + format_number(kMaxCoordinate) +
                                  " (the largest coordinate float buffers can hold)"};
  glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.eye), up = c.up;
  if (view == glm::dvec3(0)) return CameraFault{"target", "coincides with the eye"};
  if (double d = glm::length(view); d < kMinDirectionLength)
    return CameraFault{"target", "lies " + format_number(d) + " from the eye, under the " +
                                     format_number(kMinDirectionLength) + " a view direction needs"};
  double up_length = glm::length(up);
  if (!(up_length >= kMinDirectionLength && up_length <= kMaxDirectionLength))
    return CameraFault{"up", "has length " + format_number(up_length) + ", outside [" +
                                 format_number(kMinDirectionLength) + ", " + format_number(kMaxDirectionLength) + "]"};
  if (glm::length(glm::cross(up / up_length, glm::normalize(view))) < kMinUpSine)
    return CameraFault{"up", "is parallel (or nearly) to the view direction, target - eye"};
  return std::nullopt;
}

std::optional<CameraFault> planes_fault(const Camera& c) {
  double near = c.near, far = c.far;
  std::string planes = "near " + format_number(near) + " and far " + format_number(far);
  if (!(near > 0)) return CameraFault{"near", "is " + format_number(near) + ": it must be greater than 0"};
  if (!(far > near)) return CameraFault{"far", planes + ": far must be greater than near"};
  if (far / near > kMaxFarOverNear)
    return CameraFault{"near", planes + ": far / near is over the " + format_number(kMaxFarOverNear) +
                                   " that float depth can resolve"};
  if ((far - near) / far < kMinDepthExtent)
    return CameraFault{"far", planes + ": float depth cannot tell them apart ((far - near) / far is under " +
                                  format_number(kMinDepthExtent) + ")"};
  return std::nullopt;
}

}  // namespace

std::optional<CameraFault> camera_fault(const Camera& c, double aspect, glm::dvec3 origin) {
  if (auto f = fov_fault(c, aspect)) return f;
  if (auto f = position_fault(c, origin)) return f;
  return planes_fault(c);
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
