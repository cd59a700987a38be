// The brush parameters of coherent silhouettes on the GPU (Kalnins et al. 2003; the stage in
// common/strokes/brush_parameters.hpp), the twin of reference/strokes/brush_parameters.cpp,
// kept on the GPU from frame to frame: where this frame follows the renderer's last
// (GpuFrame::follows_last), the samples that frame left (gpu/strokes/brush_samples.hpp) vote
// for this frame's runs (gpu/strokes/brush_votes.hpp),
// the votes are fitted (gpu/strokes/brush_fit.hpp), which the stroke pass draws
// (gpu/strokes/stroke_samples.hpp), and this frame's runs are sampled for the next. Nothing
// is read back, and nothing per run or sample goes through the CPU. A frame that follows
// none and that none may follow (GpuFrame::may_be_followed: a still scene outside the viewer)
// does none of this: its runs take t = s, as with no votes.
#pragma once

#include "gpu/core/stage.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/brush_samples.hpp"

namespace plumbago::gpu {

// This frame's fit, which the stroke pass draws; and its brush samples (tests read them back);
// neither where the frame did no work.
inline constexpr Shared<BrushFit> kBrushFit{"brush_parameters.fit"};
inline constexpr Shared<BrushSamples> kGpuBrushSamples{"brush_parameters.gpu_samples"};

}  // namespace plumbago::gpu
