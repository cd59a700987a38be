// Decals' projection, CPU reference (SPEC 4.9, common/decal.hpp 1.): an Embree ray through
// each sample.
#pragma once

#include "common/decal.hpp"

namespace plumbago::reference {

// Every decal stroke of `scene`'s stroke files projected onto its surface, in
// decal_samples' order.
DecalSurface project_decals_by_rays(const Scene& scene);

}  // namespace plumbago::reference
