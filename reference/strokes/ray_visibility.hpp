// What the ID-image test of stroke visibility approximates (docs/conventions.md "ID image and
// visibility"): whether a world point of a feature line is seen from the eye, by Embree
// rays from the eye to it. Each point says how its own surface is told from an occluder:
// - a silhouette point lies on the smooth (interpolated-normal) silhouette, off the facets,
//   which a faceted mesh's own faces graze up to about a facet away: a hit within
//   `own_facets` of the point along the ray does not occlude it (the caller passes about
//   the size of the point's faces);
// - a point on the mesh (a crease or border on its edge, a decal or hatch on its faces,
//   own_facets = 0): a hit on a triangle that passes through the point (within 1e-5 of its
//   distance from the eye) is its own surface and the ray goes on past it; any other hit
//   before the point occludes it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"

namespace plumbago::reference {

struct RayTarget {
  glm::dvec3 point;  // world space
  double own_facets = 0;
};

std::vector<uint8_t> visible_by_rays(const Scene& scene, const std::vector<RayTarget>& targets);

}  // namespace plumbago::reference
