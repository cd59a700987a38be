// The visible runs' styles on the GPU: see gpu/strokes/run_styles.hpp.
#include "gpu/strokes/run_styles.hpp"

#include <algorithm>
#include <cmath>

#include "common/strokes/stroke.hpp"
#include "gpu/strokes/stroke_samples.hpp"

namespace plumbago::gpu {

namespace {

StyleRow style_row(const StrokeStyle& s, StyleOffsets offsets) {
  StyleRow row{};
  put_style(s, row);
  row.offsets = offsets;
  return row;
}

}  // namespace

RunStyleTables::RunStyleTables(const StrokeStyles& styles, const std::vector<StrokeStyle>& decal_styles)
    : decal_count_(decal_styles.size()) {
  for (LineKind kind : {LineKind::Crease, LineKind::Border, LineKind::Silhouette}) add_line_style(kind, styles);
  for (const StrokeStyle& s : decal_styles) {  // common/strokes/stroke.cpp decal_style
    rows_.push_back(style_row(s, kDecalPressure));
  }
  styles_buffer_ = make_buffer(rows_.data(), rows_.size() * sizeof(StyleRow));
  examples_buffer_ = make_buffer(examples_.data(), examples_.size() * sizeof(ExampleRow));
  states_buffer_ = make_buffer(states_.data(), states_.size() * sizeof(StateRow));
  targets_buffer_ = make_buffer(targets_.data(), targets_.size() * sizeof(TargetRow));
  offsets_buffer_ = make_buffer(offsets_.data(), offsets_.size() * sizeof(OffsetInput));
}

void RunStyleTables::copy_offsets(const Buffer& to) const {
  if (!offsets_.empty()) copy_buffer(offsets_buffer_, to, offsets_.size() * sizeof(OffsetInput));
}

void RunStyleTables::add_example(const OffsetExample& e) {
  examples_.push_back({e.length_px, uint32_t(offsets_.size()), uint32_t(e.offsets.size()), e.repeats ? 1u : 0u});
  lifts_.push_back(pen_lifts(e));
  for (const StrokeOffset& o : e.offsets) offsets_.push_back(offset_input(o));
}

void RunStyleTables::add_line_style(LineKind kind, const StrokeStyles& styles) {
  const StrokeStyle& style = line_style(kind, styles);
  const std::vector<OffsetExample>& drawn = drawn_examples(kind, styles);
  const RunOffsets how = run_offsets(kind, styles);
  StyleRow row = style_row(style, StyleOffsets(how));
  row.first_example = uint32_t(examples_.size());
  if (how == RunOffsets::Own) add_example(*style.offsets);
  if (how == RunOffsets::Drawn)
    for (const OffsetExample& e : drawn) add_example(e);
  row.example_count = uint32_t(examples_.size()) - row.first_example;
  if (how == RunOffsets::Synthesized) {  // OffsetSynthesizer's chain as walk() reads it
    OffsetSynthesizer chain = offset_chain(kind, styles);
    row.first_state = uint32_t(states_.size()), row.state_count = uint32_t(chain.state_count());
    row.markov = chain.is_markov(), row.step = chain.options().step_px;
    for (size_t i = 0; i < chain.state_count(); ++i) {
      const auto* to = chain.is_markov() ? &chain.targets(i) : nullptr;
      states_.push_back({chain.values()[i], chain.pressures()[i], uint32_t(targets_.size()),
                         to ? uint32_t(to->size()) : 0u, uint32_t(chain.successors()[i])});
      for (size_t k = 0; to && k < to->size(); ++k) targets_.push_back({chain.cumulative(i)[k], (*to)[k]});
    }
    row.first_start = uint32_t(targets_.size()), row.start_count = uint32_t(chain.starts().size());
    for (size_t start : chain.starts()) targets_.push_back({0.0, uint32_t(start)});
  }
  rows_.push_back(row);
}

double RunStyleTables::sample_bound(uint32_t style, double length, double runs) const {
  const StyleRow& row = rows_.at(style);
  // Every run's even samples (no example, or one made for the run), and each example's pen
  // changes over all the runs, whichever runs take it: each term adds up over runs and paths.
  const double even = gpu::sample_bound(length, runs, row.sample_px, 0, 0);
  double most = even;
  for (uint32_t k = row.first_example; k < row.first_example + row.example_count; ++k)
    most += gpu::sample_bound(length, runs, row.sample_px, examples_[k].length, lifts_[k]) - even;
  return most;
}

double RunStyleTables::synthesized_offsets(uint32_t style, double length, double runs) const {
  const StyleRow& row = rows_.at(style);  // per run: max(l, 1) / step + 3 at most, max(l, 1) <= l + 1
  if (row.offsets != kSynthesizedOffsets) return 0.0;
  double along_runs = (length + runs) / row.step + 3 * runs;
  if (style != PathTable::kSilhouetteStyle) return along_runs;
  return along_runs + runs * (std::ceil(kBrushOffsetPeriodPx / row.step) + 1);  // or along brush paths
}

void RunStyleTables::bind() const {
  const Buffer* at[] = {&styles_buffer_, &examples_buffer_, &states_buffer_, &targets_buffer_};
  for (GLuint k = 0; k < 4; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3 + k, at[k]->id());
}

}  // namespace plumbago::gpu
