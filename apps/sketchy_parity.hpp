// Stage parity of sketchy drawing (SPEC 3, SPEC 5): the enlarged geometry raster vs
// ray, the maps and the composite with both backends fed the reference's inputs.
#pragma once

#include <vector>

#include "apps/parity.hpp"

namespace plumbago {

// Each returns nothing for a scene without sketchy objects.
std::vector<StageParity> sketchy_enlarged_parity(const Scene& scene);
std::vector<StageParity> sketchy_maps_parity(const Scene& scene);
std::vector<StageParity> sketchy_composite_parity(const Scene& scene);

}  // namespace plumbago
