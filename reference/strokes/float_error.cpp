// Float error bounds of the GPU's stroke stages: see reference/strokes/float_error.hpp.
#include "reference/strokes/float_error.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago::reference {

double projection_error_px(const glm::dmat4& clip, int width, int height, glm::dvec3 p, double dp) {
  glm::dvec4 c = clip * glm::dvec4(p, 1.0), err;
  for (int r = 0; r < 4; ++r) {
    glm::dvec4 row(clip[0][r], clip[1][r], clip[2][r], clip[3][r]);
    err[r] = 5 * kU * glm::dot(glm::abs(row), glm::dvec4(glm::abs(p), 1.0)) + glm::length(row) * dp;
  }
  double w = std::abs(c.w), size = std::max(width, height);
  double ex = 0.5 * width * (err.x + std::abs(c.x / c.w) * err.w) / w;
  double ey = 0.5 * height * (err.y + std::abs(c.y / c.w) * err.w) / w;
  return 2 * (std::max(ex, ey) + 3 * kU * size);
}

double depth_error(const glm::dmat4& object_to_view, glm::dvec3 p) {
  glm::dvec4 row(object_to_view[0][2], object_to_view[1][2], object_to_view[2][2], object_to_view[3][2]);
  return 2 * 5 * kU * glm::dot(glm::abs(row), glm::dvec4(glm::abs(p), 1.0));
}

}  // namespace plumbago::reference
