// Stroke samples on the GPU (Kalnins et al. 2002, §4.1, §4.3): the twin of
// common/strokes/base_stroke.hpp 1.-5., in double, one invocation per visible run
// (shaders/strokes/stroke_samples.comp). A frame's runs are the visibility steps', on the GPU
// (gpu/strokes/window_paths.hpp): the GPU makes each run's window polyline from its path
// there; tests may give the polylines instead. The runs' styles go up (made on the CPU per
// run, with their synthesized offsets: common/strokes/stroke.hpp RunStyles). The GPU keeps each
// run's distinct points, counts its samples, places them by a prefix sum and writes them, with
// each run's record, where shaders/strokes/common_ribbon.glsl reads them, and the indirect
// draw of their ribbons. Nothing is read back.
#pragma once

#include <cstdint>
#include <vector>

#include "common/strokes/stroke.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/stroke.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

// One run as stroke_samples.comp reads it (std430).
struct RunInput {
  glm::vec4 color_layer;
  uint32_t first_point, point_count, first_offset, offset_count;
  double example_length;
  float width, alpha, taper, fade, halo, flare, sample_px, period;
  uint32_t flags, pad = 0;
};
struct OffsetInput {
  double t, displacement, pressure;
  uint32_t pen_up, pad = 0;
};
static_assert(sizeof(RunInput) == 80 && sizeof(OffsetInput) == 32, "std430 layouts of stroke_samples.comp");

// At least the samples base_stroke_samples makes of a run whose polyline is `length` px long
// in `style` (its spline is at most 11/3 as long: each span's Bézier control polygon is, as
// |v_i| <= 1), pen changes included.
double sample_bound(double length, const StrokeStyle& style);
double sample_bound(const StyledRun& r);

class StrokeSamples {
 public:
  StrokeSamples();
  // Computes the samples of `runs`, through their polylines; the buffers hold them until the
  // next call.
  void operator()(const std::vector<StyledRun>& runs);
  // The same of the runs of `visibility` over `lines`, as `tables` holds them on the GPU, in
  // `styles` (one a run): their polylines made on the GPU.
  void operator()(const WindowLines& lines, const Visibility& visibility, const std::vector<StrokeStyle>& styles,
                  const RunTables& tables);
  // The samples and runs to SSBO bindings 0 and 1, as common_ribbon.glsl reads them.
  void bind() const;
  // The ribbons' draw (DrawArraysIndirectCommand, GL_TRIANGLES); none without runs.
  const Buffer* draw() const { return runs_ == 0 ? nullptr : &draw_; }
  // Read back, for tests: every sample slot (a run's from its record's `first`), every run's record.
  std::vector<SampleRecord> samples() const;
  std::vector<RunRecord> runs() const;

 private:
  struct Inputs;
  void run(const Inputs& in, const RunTables* tables);
  void make_polylines(const RunTables& tables);

  Program polyline_count_, polyline_write_, count_, write_, args_;
  ExclusiveScan scan_;
  Buffer runs_in_, points_, offsets_, counts_, distinct_, states_, bases_, samples_, runs_out_, draw_;
  uint32_t runs_ = 0, capacity_ = 0;
};

}  // namespace plumbago::gpu
