// Light sums shared by the stages that shade (Lee et al. 2006, §4.1, Eq. 1; §3, §5.2).
#pragma once

#include <vector>

#include "common/scene/scene.hpp"

namespace plumbago {

// sum over lights of intensity * max(0, n.L); the directions must be unit.
float light_sum(glm::vec3 n, const std::vector<Light>& unit_lights);

// The lights with unit directions, in world space or turned into view space.
std::vector<Light> unit_world_lights(const Scene& scene);
std::vector<Light> view_space_lights(const Scene& scene);

}  // namespace plumbago
