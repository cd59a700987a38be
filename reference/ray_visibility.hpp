// What the ID-image test of stroke visibility approximates (SPEC 5 "ID image and
// visibility"): whether a world point is seen from the eye, by an Embree occlusion ray
// from the eye that stops short of the point by `relative_gap` of its distance (a point on
// the surface would otherwise occlude itself, and a silhouette point's ray grazes it).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene.hpp"

namespace plumbago::reference {

std::vector<uint8_t> visible_by_rays(const Scene& scene, const std::vector<glm::dvec3>& points, double relative_gap = 1e-3);

}  // namespace plumbago::reference
