// Edge detection, CPU reference (Nienhaus & Döllner 2003, as given in Pacheco §2).
#pragma once

#include "common/pencil/edge_detect.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago::reference {

// Contour darkness d = 1 - I_n I_z per pixel (1 channel).
Image contour_darkness(const GBuffer& g, const EdgeDetectParams& p);

}  // namespace plumbago::reference
