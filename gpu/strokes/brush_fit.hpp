// The fit of coherent silhouettes on the GPU (Kalnins et al. 2003): steps 3. and 4. of
// common/strokes/coherent_silhouettes.hpp (groups, sections, and each section's t fitted on
// its knots), in double, one invocation per run (shaders/strokes/brush_fit.comp), the twin of
// fit_brush_parameter. Its votes are given per run: gpu/strokes/brush_votes.hpp makes them
// per sample on the GPU; bucketing them by run there, and the stage that puts samples, votes
// and fit in a frame, are not built yet.
#pragma once

#include <vector>

#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

// The knots a run's fit may write: n + 1 a section of length L_i, n <= L_i / knot_px + 1,
// at most two sections a vote.
double knot_bound(double length_px, size_t votes, const CoherenceParams& p);

class BrushFit {
 public:
  BrushFit();
  // Fits run r's parameter from votes[r] (any order; their `run` is not read), lengths[r]
  // its window length; the knots stay on the GPU until the next call.
  void operator()(const std::vector<std::vector<BrushVote>>& votes, const std::vector<double>& lengths,
                  const CoherenceParams& p);
  // Read back, for tests: each run's knots (none where it has no claim, as the reference).
  std::vector<BrushParameter> parameters() const;

 private:
  Program fit_;
  ScratchBuffer votes_, runs_, groups_, claims_, rows_, knots_, params_;
  size_t run_count_ = 0;
};

}  // namespace plumbago::gpu
