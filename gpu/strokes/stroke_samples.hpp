// Stroke samples on the GPU (Kalnins et al. 2002, §4.1, §4.3): the twin of
// common/strokes/base_stroke.hpp 1.-5., in double, one invocation per visible run
// (shaders/strokes/stroke_samples.comp). A frame's runs are the visibility steps', on the GPU
// (gpu/strokes/window_paths.hpp): step 0 (shaders/strokes/run_inputs.comp) gives each its
// window polyline and its style, with its offsets stamped or synthesized, from the scene's
// style tables (gpu/strokes/run_styles.hpp); tests may give the polylines and styles instead,
// and with them a brush parameter per run (Kalnins et al. 2003, common/strokes/base_stroke.hpp
// 4., 6.: knots after the run's points); the frame's own runs take theirs from the GPU's fit
// (gpu/strokes/brush_fit.hpp, shaders/strokes/run_knots.comp) where one is given.
// The GPU then keeps each run's distinct points, counts its samples, places them by a prefix
// sum and writes them, with each run's record, where shaders/strokes/common_ribbon.glsl reads
// them, and the indirect draw of their ribbons. Every step goes over the runs the GPU
// listed, by indirect dispatches and prefix sums over their count: nothing is read back, and
// the CPU sizes the buffers from the paths' run bounds alone (gpu/strokes/window_paths.hpp
// RunBound), in a frame that sizes them; the frames after keep them: a run whose points or
// offsets would pass them is left out (run_inputs.comp), and so are samples past them.
#pragma once

#include <cstdint>
#include <vector>

#include "common/strokes/stroke.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/run_styles.hpp"
#include "gpu/strokes/stroke.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

// At least the samples base_stroke_samples makes of `runs` runs whose polylines are `length`
// px long together, resampled every `sample_px`, stamped with an example `example_length` px
// long with `lifts` pen lifts (a spline is at most 11/3 as long as its polyline: each span's
// Bézier control polygon is, as |v_i| <= 1), pen changes included; and of a run in its style.
double sample_bound(double length, double runs, double sample_px, double example_length, double lifts);
double sample_bound(const StyledRun& r);
double pen_lifts(const OffsetExample& e);

class StrokeSamples {
 public:
  StrokeSamples();
  // Computes the samples of `runs`, through their polylines; the buffers hold them until the
  // next call.
  void operator()(const std::vector<StyledRun>& runs);
  // The same of the runs that `tables` holds on the GPU, however many it lists: their
  // polylines and styles made on the GPU (`styles`; `seed`, the scene's), the buffers sized
  // from the paths' run bounds, or (tables not sized: RunTables::sized) as the last sized call
  // sized them.
  // With `brushes`, each run takes the brush parameter the GPU fitted for it (Kalnins et al.
  // 2003, gpu/strokes/brush_fit.hpp; shaders/strokes/run_knots.comp), else t = s. Where
  // silhouettes are `coherent` (or `brushes` given) a synthesized style's silhouette runs draw
  // their brush paths' offsets (common/strokes/coherent_silhouettes.hpp 5.): the fit's, else
  // new ones.
  void operator()(const RunTables& tables, const RunStyleTables& styles, uint32_t seed,
                  const BrushFit* brushes = nullptr, bool coherent = false);
  // The samples and runs to SSBO bindings 0 and 1, as common_ribbon.glsl reads them.
  void bind() const;
  // The ribbons' draw (DrawArraysIndirectCommand, GL_TRIANGLES); none without runs.
  const Buffer* draw() const { return runs_ == 0 ? nullptr : &draw_.buffer; }
  // Read back, for tests: every sample slot (a run's from its record's `first`), every run
  // row's record (the runs listed first; the rows the bound adds after them are not written).
  std::vector<SampleRecord> samples() const;
  std::vector<RunRecord> runs() const;

 private:
  // What the buffers are sized by: the runs' rows, the offsets' rows, and bounds on the
  // samples and on the points.
  struct Sizes {
    size_t runs = 0, offset_rows = 0;
    double bound = 0, point_bound = 0;
  };
  struct Inputs;
  void run(const Inputs& in, const RunTables* tables, const RunStyleTables* styles, const BrushFit* brushes);
  void make_inputs(const RunTables& tables, const RunStyleTables& styles, const BrushFit* brushes);
  void over_knots(const Program& step, const BrushFit& brushes) const;
  void over_runs(const Program& step) const;

  Program inputs_args_, inputs_count_, inputs_write_, knots_count_, knots_copy_, count_, write_, args_;
  ExclusiveScan scan_;
  // Kept across frames: the steps write every row of the runs listed, and the prefix sums
  // read only the rows before each.
  ScratchBuffer runs_in_, points_, offsets_, distinct_, states_, bases_, samples_, runs_out_, draw_;
  ScratchBuffer counts_, point_counts_, offset_counts_;
  Buffer run_args_;
  uint32_t runs_ = 0, capacity_ = 0;
  Sizes sized_;  // the last call's from run bounds
};

}  // namespace plumbago::gpu
