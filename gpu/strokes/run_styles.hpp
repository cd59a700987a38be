// The visible runs' styles on the GPU (Kalnins et al. 2002, §4.1, §4.3, §5.3): the scene's line
// styles, decal styles, drawn offset examples and Markov chains (common/strokes/stroke.hpp
// RunStyles), put up once as tables; shaders/strokes/run_inputs.comp gives each run its style
// from them, stamps an example or synthesizes one for it, and writes the RunInput the stroke
// samples read (gpu/strokes/stroke_samples.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

// One run as stroke_samples.comp reads it (shaders/strokes/stroke_runs.glsl; std430).
struct RunInput {
  glm::vec4 color_layer;
  uint32_t first_point, point_count, first_offset, offset_count;
  double example_length;
  float width, alpha, taper, fade, halo, flare, sample_px, period;
  uint32_t flags;
  uint32_t knot_count = 0;  // its brush parameter's knots, after its points (none: t = s)
};
struct OffsetInput {
  double t, displacement, pressure;
  uint32_t pen_up, pad = 0;
};
static_assert(sizeof(RunInput) == 80 && sizeof(OffsetInput) == 32, "std430 layouts of stroke_runs.glsl");

enum RunFlags : uint32_t {
  kClosed = 1,
  kOccludedStart = 2,
  kOccludedEnd = 4,
  kPressureWidth = 8,
  kPressureAlpha = 16,
  kRepeats = 32,
  kUnscaled = 64
};  // stroke_runs.glsl's

// A style's fields as RunInput and StyleRow hold them (flags: its pressure's), and an
// offset as the shaders read it.
template <class Row>
void put_style(const StrokeStyle& s, Row& row) {
  row.color_layer = glm::vec4(s.color_r, s.color_g, s.color_b, float(int(s.texture)));
  row.width = s.width_px, row.alpha = s.alpha, row.taper = s.taper_px, row.fade = s.fade_px, row.halo = s.halo_px;
  row.flare = s.flare, row.sample_px = s.sample_px, row.period = s.texture_period_px;
  row.flags = (s.pressure_width ? kPressureWidth : 0u) | (s.pressure_alpha ? kPressureAlpha : 0u);
}
inline OffsetInput offset_input(const StrokeOffset& o) {
  return {o.t, o.displacement_px, o.pressure, o.pen_up ? 1u : 0u};
}

// The tables of run_inputs.comp (std430).
struct StyleRow {
  glm::vec4 color_layer;
  float width, alpha, taper, fade, halo, flare, sample_px, period;
  uint32_t flags, offsets, first_example, example_count, first_state, state_count, first_start, start_count, markov,
      pad = 0;
  double step;
};
struct ExampleRow {
  double length;
  uint32_t first_offset, offset_count, repeats, pad = 0;
};
struct StateRow {
  double value, pressure;
  uint32_t first_target, target_count, successor, pad = 0;
};
struct TargetRow {
  double cumulative;
  uint32_t to, pad = 0;
};
static_assert(sizeof(StyleRow) == 96 && sizeof(ExampleRow) == 24 && sizeof(StateRow) == 32 && sizeof(TargetRow) == 16,
              "std430 layouts of run_inputs.comp");

// How a style's runs get their offsets (run_inputs.comp): RunOffsets, and a decal's pressure.
enum StyleOffsets : uint32_t { kNoOffsets, kOwnOffsets, kDrawnOffsets, kSynthesizedOffsets, kDecalPressure };

class RunStyleTables {
 public:
  // Styles 0-2: the creases', borders' and silhouettes' (with their Markov chains, built
  // here); 3 + d: decal style d.
  RunStyleTables(const StrokeStyles& styles, const std::vector<StrokeStyle>& decal_styles);

  size_t decal_count() const { return decal_count_; }
  // The examples' own offsets, which the frame's offsets buffer starts with: how many, and
  // copied there on the GPU.
  uint32_t own_offsets() const { return uint32_t(offsets_.size()); }
  void copy_offsets(const Buffer& to) const;
  // At least the samples of `runs` runs `length` px long together in style `style`, of one
  // path or several, whichever examples they stamp (their pen lifts included), and the
  // offsets they make themselves (a synthesized example's, over the run or, a silhouette's
  // where they are coherent, over its brush path's period: common/strokes/coherent_silhouettes.hpp
  // 5.; a decal's are bounded by its path's points).
  double sample_bound(uint32_t style, double length, double runs) const;
  double synthesized_offsets(uint32_t style, double length, double runs) const;
  bool decal(uint32_t style) const { return rows_.at(style).offsets == kDecalPressure; }
  // The tables to SSBO bindings 3-6 of run_inputs.comp.
  void bind() const;

 private:
  void add_line_style(LineKind kind, const StrokeStyles& styles);
  void add_example(const OffsetExample& e);

  size_t decal_count_ = 0;
  std::vector<StyleRow> rows_;
  std::vector<ExampleRow> examples_;
  std::vector<double> lifts_;  // per example, its pen lifts
  std::vector<StateRow> states_;
  std::vector<TargetRow> targets_;
  std::vector<OffsetInput> offsets_;
  Buffer styles_buffer_, examples_buffer_, states_buffer_, targets_buffer_, offsets_buffer_;
};

}  // namespace plumbago::gpu
