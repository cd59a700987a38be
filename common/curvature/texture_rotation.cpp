#include "common/curvature/texture_rotation.hpp"

#include <cmath>

namespace plumbago {

WindowAngle window_angle(const ProjectionInfo& proj, glm::vec3 p, glm::vec3 d, float min_projected) {
  glm::vec4 c = proj.view_projection * glm::vec4(p, 1.0f);
  glm::vec4 e = proj.view_projection * glm::vec4(d, 0.0f);
  glm::vec2 jd = glm::vec2(proj.width, proj.height) * 0.5f * (glm::vec2(e) * c.w - glm::vec2(c) * e.w) / (c.w * c.w);
  float across = proj.height / (2.0f * proj.tan_half_fov * c.w);  // |J d| of a unit d across the view ray
  bool reliable = c.w > 0 && glm::length(jd) >= min_projected * across && std::isfinite(jd.x) && std::isfinite(jd.y);
  return {reliable ? std::atan2(jd.y, jd.x) : 0.0f, reliable};
}

float stroke_angle(const ProjectionInfo& proj, glm::vec3 p, glm::vec3 primary, glm::vec3 secondary,
                   float min_projected) {
  WindowAngle a = window_angle(proj, p, primary, min_projected);
  if (a.reliable) return a.theta;
  WindowAngle b = window_angle(proj, p, secondary, min_projected);
  return b.reliable ? b.theta + 1.5707963f : 0.0f;
}

}  // namespace plumbago
