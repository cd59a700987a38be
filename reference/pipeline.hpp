// The CPU reference backend: runs the passes a scene's effects need (common/passes.hpp).
#pragma once

#include "common/frame.hpp"
#include "common/scene.hpp"

namespace plumbago::reference {

Frame render(const Scene& scene, const FrameOptions& options = {});

}  // namespace plumbago::reference
