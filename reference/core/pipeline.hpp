// The CPU reference backend: runs the stages a scene's effects need (common/core/passes.hpp),
// each through its registered implementation (reference/core/stage.hpp).
#pragma once

#include "common/core/frame.hpp"
#include "common/scene/scene.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

Frame render(const Scene& scene, const FrameOptions& options = {});

// The frame with every buffer its stages made (parity reads its stages' inputs there);
// `ran` gets what ran with its time. `previous`: the data of the path's previous frame
// (Carry::before), where it follows one.
ReferenceFrame run_stages(const Scene& scene, std::vector<PassTime>& ran, const DataTable* previous = nullptr);

}  // namespace plumbago::reference
