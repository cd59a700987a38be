// Interior pencil shading, CPU reference (Lee et al. 2006, §5.1-5.5; formulas in
// common/pencil/pencil_interior.hpp).
#pragma once

#include <vector>

#include "common/pencil/interior_intensity.hpp"
#include "common/pencil/pencil_interior.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago::reference {

// D_i per pixel (1 channel). `paper_normal` may be empty when !options.paper.
Image interior_darkness(const GBuffer& g, const Image& interior_intensity, const std::vector<Image>& stack,
                        const Image& paper_normal, const InteriorOptions& options, const InteriorParams& p, float mu_p);

}  // namespace plumbago::reference
