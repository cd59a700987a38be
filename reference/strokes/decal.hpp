// Decals' projection, CPU reference (Kalnins et al. 2002, §3, §4.5, common/strokes/decal.hpp 1.): an Embree ray through
// each sample.
#pragma once

#include <embree3/rtcore.h>

#include "common/strokes/decal.hpp"

namespace plumbago::reference {

// The first surface an Embree ray through window point p of `file`'s camera meets.
DecalPoint first_surface_hit(RTCScene scene, const StrokeFile& file, const DrawnPoint& p);

// Every decal stroke of `scene`'s stroke files projected onto its surface, in
// decal_samples' order.
DecalSurface project_decals_by_rays(const Scene& scene);

}  // namespace plumbago::reference
