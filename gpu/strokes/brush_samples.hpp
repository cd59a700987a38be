// The brush samples of coherent silhouettes on the GPU (Kalnins et al. 2003): step 1. of
// common/strokes/coherent_silhouettes.hpp, in double, one invocation per visible run as the
// visibility steps leave them on the GPU (shaders/strokes/brush_samples.comp), the twin of
// brush_samples: what the next frame's votes (gpu/strokes/brush_votes.hpp) project.
#pragma once

#include <vector>

#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class BrushSamples {
 public:
  BrushSamples();
  // The samples of the silhouette runs of `tables`, seen by `camera` in a width x height
  // window; run i parameterized by parameters[i] (none given, or past its end: t = s). They
  // stay on the GPU until the next call, as many as the runs' bounds hold.
  void operator()(const RunTables& tables, const Camera& camera, int width, int height,
                  const std::vector<BrushParameter>& parameters, const CoherenceParams& p);
  // Read back, for tests, while the tables live: the samples, in the order of their runs.
  std::vector<BrushSample> samples() const;

 private:
  Program count_, write_;
  ExclusiveScan scan_;
  ScratchBuffer counts_, run_knots_, knots_, samples_, frame_;
  uint32_t capacity_ = 0, runs_ = 0;
  GpuCount listed_;  // the runs listed: the tables' (tests read it back)
};

}  // namespace plumbago::gpu
