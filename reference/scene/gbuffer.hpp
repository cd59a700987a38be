// Ray-traced G-buffer (docs/stages.md, gbuffer), the CPU reference for gpu/scene/gbuffer.cpp: one Embree
// primary ray through each pixel center, over the same world-space geometry.
#pragma once

#include "common/scene/gbuffer.hpp"

namespace plumbago::reference {

// Every channel of GBuffer (common/scene/gbuffer.hpp) for a width x height image of `scene`.
// Back faces keep the mesh's orientation (their normals point away from the camera).
// `curvature` (one per object, or none) gives the corner angles of Lee et al. 2006, §5.3.
GBuffer trace_gbuffer(const Scene& scene, int width, int height, const std::vector<Curvature>& curvature = {});

}  // namespace plumbago::reference
