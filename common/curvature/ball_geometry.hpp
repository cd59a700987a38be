// Exact measures of mesh pieces inside a ball, for the curvature tensor's |e ∩ B| and
// |B| (Lee et al. 2006, §5.3; Alliez et al. 2003).
#pragma once

#include <glm/glm.hpp>

namespace plumbago {

// Length of the segment [p, q] inside the ball of center c and radius r.
double segment_length_in_ball(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& c, double r);

// The same as a fraction of the segment's length (0 for a zero-length segment).
double segment_fraction_in_ball(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& c, double r);

// Area of triangle (a, b, d) inside the ball of center c and radius r: the ball cuts the
// triangle's plane in a disk, and the area of triangle ∩ disk is the sum over the
// triangle's edges of the signed area of disk ∩ (center, edge).
double triangle_area_in_ball(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d, const glm::dvec3& c,
                             double r);

// The same with the triangle's N = (b - a) x (d - a) and |N| already known.
double triangle_area_in_ball(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d, const glm::dvec3& c,
                             double r, const glm::dvec3& N, double N_length);

}  // namespace plumbago
