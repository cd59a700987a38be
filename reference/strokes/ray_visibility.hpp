// What the ID-image test of stroke visibility approximates (docs/conventions.md "ID image and
// visibility"): whether a world point of a feature line is seen from the eye, by Embree
// rays from the eye to it. A hit within `ignore[k]` of point k does not occlude it: the
// surface the point lies on. A silhouette point is on the smooth (interpolated-normal)
// silhouette, which a faceted mesh's own faces graze up to about a facet away, so the
// caller passes about the size of the point's faces.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"

namespace plumbago::reference {

std::vector<uint8_t> visible_by_rays(const Scene& scene, const std::vector<glm::dvec3>& points,
                                     const std::vector<double>& ignore);

}  // namespace plumbago::reference
