// The votes of coherent silhouettes on the GPU (Kalnins et al. 2003): step 2. of
// common/strokes/coherent_silhouettes.hpp, in double, one invocation per brush sample of the
// last frame (shaders/strokes/brush_votes.comp), the twin of brush_votes: over this frame's
// visible silhouette runs as the visibility steps leave them on the GPU (RunTables): from
// samples given, or from those gpu/strokes/brush_samples.hpp left on the GPU last frame.
#pragma once

#include <vector>

#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/groups.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/brush_samples.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class BrushVotes {
 public:
  BrushVotes();
  // Each of `previous` seen by `camera` in a width x height window votes for a run of
  // `tables`; the votes stay on the GPU until the next call, one slot a sample.
  void operator()(const std::vector<BrushSample>& previous, const Camera& camera, int width, int height,
                  const RunTables& tables, const CoherenceParams& p);
  // The same from the samples `previous` left on the GPU: one slot each its buffer holds,
  // those past the samples it wrote without a vote; nothing goes through the CPU.
  void operator()(const BrushSamples& previous, const Camera& camera, int width, int height, const RunTables& tables,
                  const CoherenceParams& p);
  // Read back, for tests: the votes in the order of the samples that made one.
  std::vector<BrushVote> votes() const;
  // One slot a sample (shaders/strokes/brush_votes.comp Vote): what the fit buckets by run.
  const Buffer& buffer() const { return votes_.buffer; }
  size_t slots() const { return slots_; }

 private:
  // `slots` slots, the first `total` (a uint on the GPU) of `samples` voting.
  void vote(const Buffer& samples, const Buffer& total, size_t slots, const Camera& camera, int width, int height,
            const RunTables& tables, const CoherenceParams& p);

  Program pieces_, bin_, vote_;  // the runs' pieces, their cells, then the votes
  ExclusiveScan scan_;           // the cells' counts made their starts
  GroupsOver over_;              // the runs listed, then the pieces
  ScratchBuffer samples_, total_, votes_, frame_, pieces_at_, counts_, cells_, entries_, longs_;
  size_t slots_ = 0;
};

}  // namespace plumbago::gpu
