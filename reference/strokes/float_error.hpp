// What the GPU's float evaluation of a stroke stage may differ from the reference's double
// one: first-order forward error bounds (unit roundoff u = 2^-24), each doubled, since GLSL
// lets division and inversesqrt be off by 2.5 and 2 ulp; the second-order terms are left
// out. The stages' parity bounds are made of them (PLUMBAGO_REFERENCE_BOUND).
#pragma once

#include <glm/glm.hpp>

namespace plumbago::reference {

constexpr double kU = 0x1p-24;

// The window error (px) of the float projection of object point p, itself off by `dp`:
// each clip coordinate a four-term dot of the float matrix row (5u, the entries' rounding
// included), then the division by w and the viewport (3u of the window size). `clip`:
// object to clip space.
double projection_error_px(const glm::dmat4& clip, int width, int height, glm::dvec3 p, double dp);

// The error of the float linear depth d = depth_row · (p, 1): a four-term dot (5u), doubled.
double depth_error(const glm::dmat4& object_to_view, glm::dvec3 p);

}  // namespace plumbago::reference
