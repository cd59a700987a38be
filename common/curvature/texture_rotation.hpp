// Texture rotation (Lee §5.3): the window-space angle of a curvature
// direction d at a vertex p, projected with the Jacobian of the projection (not a finite
// difference):
//   c = M (p, 1),  e = M (d, 0),  J d = (W/2, H/2) (e.xy c.w - c.xy e.w) / c.w^2
//   theta = atan2((J d).y, (J d).x)
// A direction nearly parallel to the view ray projects short and its angle is noise:
// where |J d| is below min_projected of the length a unit direction across the view
// ray would have (H / (2 tan(fov/2) c.w) pixels), the other principal direction turned
// by 90 degrees is used; if both are short, the screen x axis (theta = 0). Never NaN.
#pragma once

#include <glm/glm.hpp>

namespace plumbago {

struct ProjectionInfo {
  glm::mat4 view_projection;  // M = P V (world to clip)
  float width, height;        // window size, pixels
  float tan_half_fov;         // tan(fov_y / 2)
};

// Angle of `d` at `p`, and whether it is long enough to trust.
struct WindowAngle {
  float theta;
  bool reliable;
};
WindowAngle window_angle(const ProjectionInfo& proj, glm::vec3 p, glm::vec3 d, float min_projected);

// theta of `primary`, else of `secondary` + 90 degrees, else 0 (the rule of Lee et al. 2006, §5.3).
float stroke_angle(const ProjectionInfo& proj, glm::vec3 p, glm::vec3 primary, glm::vec3 secondary,
                   float min_projected);

}  // namespace plumbago
