// The CPU reference backend: runs the stages a scene's effects need (common/passes.hpp),
// each through its registered implementation (reference/stage.hpp).
#pragma once

#include "common/frame.hpp"
#include "common/scene.hpp"
#include "reference/stage.hpp"

namespace plumbago::reference {

Frame render(const Scene& scene, const FrameOptions& options = {});

// The frame with every buffer its stages made (parity reads its stages' inputs there);
// `ran` gets what ran with its time.
ReferenceFrame run_stages(const Scene& scene, std::vector<PassTime>& ran);

}  // namespace plumbago::reference
