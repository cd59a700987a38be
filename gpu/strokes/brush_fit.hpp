// The fit of coherent silhouettes on the GPU (Kalnins et al. 2003): steps 3. and 4. of
// common/strokes/coherent_silhouettes.hpp (groups, sections, and each section's t fitted on
// its knots), in double, one invocation per run (shaders/strokes/brush_fit.comp), the twin of
// fit_brush_parameter: from votes given per run, or from those gpu/strokes/brush_votes.hpp
// left on the GPU (gpu/strokes/brush_parameters.hpp puts samples, votes and fit in a frame).
#pragma once

#include <vector>

#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/groups.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/brush_votes.hpp"

namespace plumbago::gpu {

// The knots a run's fit may write: n + 1 a section of length L_i, n <= L_i / knot_px + 1,
// at most two sections a vote.
double knot_bound(double length_px, size_t votes, const CoherenceParams& p);

// A run's record in BrushFit::runs_buffer() (std430, shaders/strokes/fit_run.glsl FitRun):
// its window length, its votes, its knots in knots_buffer() and its brush path.
struct FitRunRecord {
  double length;
  uint32_t first_vote, vote_count, first_knot, knot_count = 0, path = kNewBrushPath, pad = 0;
};

class BrushFit {
 public:
  BrushFit();
  // Fits run r's parameter from votes[r] (any order; their `run` is not read), lengths[r]
  // its window length; the knots stay on the GPU until the next call.
  void operator()(const std::vector<std::vector<BrushVote>>& votes, const std::vector<double>& lengths,
                  const CoherenceParams& p);
  // The same from the votes `votes` left on the GPU, for the runs of `tables` (a run's
  // length: s1 - s0), however many it lists: the votes bucketed by run there
  // (shaders/strokes/brush_buckets.comp), each run's knots placed by its knot_bound.
  void operator()(const BrushVotes& votes, const RunTables& tables, const CoherenceParams& p);
  // Read back, for tests (while the tables live): each run's knots and brush path (none and
  // a new one where it has no claim, as the reference).
  std::vector<RunBrush> parameters() const;
  // On the GPU (shaders/strokes/brush_fit.comp): per run its FitRunRecord, the knots, and
  // how many knots the buffer holds.
  const Buffer& runs_buffer() const { return runs_.buffer; }
  const Buffer& knots_buffer() const { return knots_.buffer; }
  double knot_capacity() const { return double(knots_.bytes / sizeof(glm::dvec2)); }

 private:
  void reserve(size_t votes, double knots);
  void fit();

  Program fit_, count_, scatter_, bounds_, runs_step_;
  ExclusiveScan scan_;
  GroupsOver over_listed_;       // the runs listed, where the tables'
  GroupsOver over_each_run_{1};  // the same, a workgroup each (the fit's)
  ScratchBuffer votes_, runs_, groups_, claims_, rows_, knots_, params_, counts_, fill_;
  size_t run_count_ = 0;
  GpuCount listed_;  // the runs listed, where the tables' (else run_count_)
};

}  // namespace plumbago::gpu
