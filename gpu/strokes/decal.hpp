// Decals' projection on the GPU (Kalnins et al. 2002, §3, §4.5, common/strokes/decal.hpp 1.): through the G-buffer
// rendered with each stroke file's camera.
#pragma once

#include "common/strokes/decal.hpp"

namespace plumbago::gpu {

// Every decal stroke of `scene`'s stroke files projected onto its surface, in
// decal_samples' order. Needs the GL context.
DecalSurface project_decals_through_gbuffer(const Scene& scene);

}  // namespace plumbago::gpu
