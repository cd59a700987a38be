// The brush samples of coherent silhouettes on the GPU (Kalnins et al. 2003): step 1. of
// common/strokes/coherent_silhouettes.hpp, in double, one invocation per visible run as the
// visibility steps leave them on the GPU (shaders/strokes/brush_samples.comp), the twin of
// brush_samples: what the next frame's votes (gpu/strokes/brush_votes.hpp) project.
#pragma once

#include <vector>

#include "common/strokes/coherent_silhouettes.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/groups.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class BrushFit;  // gpu/strokes/brush_fit.hpp

class BrushSamples {
 public:
  BrushSamples();
  // The samples of the silhouette runs of `tables`, seen by `camera` in a width x height
  // window; run i drawn with brushes[i] (none given, or past its end: t = s, a new brush path
  // keyed with `seed`, the scene's). They stay on the GPU until the next call, as many as the
  // runs' bounds hold.
  void operator()(const RunTables& tables, const Camera& camera, int width, int height,
                  const std::vector<RunBrush>& brushes, const CoherenceParams& p, uint32_t seed);
  // The same, run i drawn with the GPU's fit for the same tables (null: t = s, new brush
  // paths): nothing goes through the CPU but the tables' bounds.
  void operator()(const RunTables& tables, const Camera& camera, int width, int height, const BrushFit* fit,
                  const CoherenceParams& p, uint32_t seed);
  // Read back, for tests: the samples, in the order of their runs.
  std::vector<BrushSample> samples() const;
  // On the GPU (shaders/strokes/brush_samples.comp Sample), what the next frame's votes read
  // (gpu/strokes/brush_votes.hpp): the samples, how many were written (one uint), and how
  // many the buffer holds.
  const Buffer& buffer() const { return samples_.buffer; }
  const Buffer& total() const { return total_.buffer; }
  uint32_t capacity() const { return capacity_; }

 private:
  // Samples every run of `tables`, its knots where `fit_runs` is given.
  void sample(const RunTables& tables, const Camera& camera, int width, int height, const Buffer* fit_runs,
              const Buffer& knots, const CoherenceParams& p, uint32_t seed);

  Program count_, write_;
  ExclusiveScan scan_;
  GroupsOver over_listed_;  // the runs listed
  ScratchBuffer counts_, fit_runs_, knots_, samples_, frame_, total_;
  uint32_t capacity_ = 0;
};

}  // namespace plumbago::gpu
