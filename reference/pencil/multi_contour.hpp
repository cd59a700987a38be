// Multiple contour drawing, CPU reference (Lee §4.2-4.3, Pacheco §4).
#pragma once

#include <vector>

#include "common/pencil/distortion.hpp"
#include "common/util/image.hpp"

namespace plumbago::reference {

// Contour darkness of all copies together (1 channel):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
Image multi_contour_darkness(const Image& lit_contour_darkness, const std::vector<Image>& offset_grids,
                             const Image& contour_texture, const std::vector<glm::vec2>& texture_shifts,
                             const ContourParams& p);

}  // namespace plumbago::reference
