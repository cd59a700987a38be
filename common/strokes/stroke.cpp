// The stroke raster's triangles (Kalnins et al. 2002, §4.1): see common/strokes/stroke.hpp.
#include "common/strokes/stroke.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include "common/strokes/offset_synthesis.hpp"
#include "common/strokes/stroke_textures.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago {

namespace {

// The drawn pressure of a decal path at window arc length s (linear between its points).
double pressure_at(const WindowPath& path, double s) {
  size_t k = segment_at(path, s), next = std::min(k + 1, path.window.size() - 1);
  double length = path.arc_px[next] - path.arc_px[k];
  double t = length > 0 ? std::clamp((s - path.arc_px[k]) / length, 0.0, 1.0) : 0.0;
  return path.pressure[k] + t * (path.pressure[next] - path.pressure[k]);
}

// A decal's style over one run (common/strokes/decal.hpp 3.): an offsets example of zero
// displacement carrying the path's pressure at the run's ends and at every path point
// between. It spans the run (at least 1 px, an example's least length) and does not repeat.
StrokeStyle decal_style(const StrokeStyle& decal, const WindowPath& path, const VisibleRun& run) {
  StrokeStyle style = decal;
  double length = std::max(run.s1 - run.s0, 1.0);
  OffsetExample pressure{length, {{0.0, 0.0, pressure_at(path, run.s0), false}}};
  for (size_t k = 0; k < path.arc_px.size(); ++k)
    if (path.arc_px[k] > run.s0 && path.arc_px[k] < run.s1)
      pressure.offsets.push_back({(path.arc_px[k] - run.s0) / length, 0.0, path.pressure[k], false});
  pressure.offsets.push_back({(run.s1 - run.s0) / length, 0.0, pressure_at(path, run.s1), false});
  pressure.repeats = false;
  style.offsets = pressure;
  style.synthesis = OffsetSynthesis::Stamp;
  return style;
}

// The finest resampling step any run of `lines` can take: its line kinds' styles', its
// decals' and hatches'.
double finest_sample_px(const WindowLines& lines, const StrokeStyles& styles) {
  double finest = std::min({styles.crease.sample_px, styles.border.sample_px, styles.silhouette.sample_px});
  for (const StrokeStyle& s : lines.decal_styles) finest = std::min(finest, double(s.sample_px));
  return finest;
}

// What the strokes would take, against the memory budget before any is made. Per spline
// sample (twice a run's window length over the finest step, as a spline through the run's
// points may run longer than they do, and its two ends): its record, and its two
// triangles' vertices as the reference's ribbon makes them and as it draws them (the GPU
// expands them from a 32-byte copy of the sample instead).
void check_stroke_memory(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles) {
  double step = finest_sample_px(lines, styles), length = 0;
  for (const VisibleRun& run : visibility.runs) length += run.s1 - run.s0;
  double samples = 2 * length / step + 2.0 * double(visibility.runs.size());
  char what[200];
  std::snprintf(what, sizeof what, "the strokes of %zu visible runs (%.3g px long, resampled every %g px)",
                visibility.runs.size(), length, step);
  check_memory_budget(what, samples * double(sizeof(StrokeSample) + 6 * (sizeof(RibbonVertex) + sizeof(StrokeVertex))));
}

}  // namespace

const StrokeStyle& line_style(LineKind kind, const StrokeStyles& styles) {
  switch (kind) {
    case LineKind::Crease:
      return styles.crease;
    case LineKind::Border:
      return styles.border;
    case LineKind::Silhouette:
      break;
    case LineKind::Decal:
      break;  // its own style: RunStyles::of
    case LineKind::Hatching:
      break;
  }
  return styles.silhouette;
}

const std::vector<OffsetExample>& drawn_examples(LineKind kind, const StrokeStyles& styles) {
  return kind == LineKind::Silhouette ? styles.silhouette_examples : styles.crease_examples;
}

RunOffsets run_offsets(LineKind kind, const StrokeStyles& styles) {
  const StrokeStyle& style = line_style(kind, styles);
  const bool drawn = !drawn_examples(kind, styles).empty();
  if (!drawn && !style.offsets) return RunOffsets::None;
  if (style.synthesis == OffsetSynthesis::Markov) return RunOffsets::Synthesized;
  return drawn ? RunOffsets::Drawn : RunOffsets::Own;
}

OffsetSynthesizer offset_chain(LineKind kind, const StrokeStyles& styles) {
  const std::vector<OffsetExample>& drawn = drawn_examples(kind, styles);
  return drawn.empty() ? OffsetSynthesizer(*line_style(kind, styles).offsets) : OffsetSynthesizer(drawn);
}

uint32_t brush_path_key(const RunBrush& brush, uint32_t seed, const WindowPath& path, uint32_t ordinal) {
  return brush.path != kNewBrushPath ? brush.path : stream_key({seed, path.key, ordinal, kOffsetWalk});
}

StrokeStyle RunStyles::of(const WindowPath& path, const VisibleRun& run, uint32_t ordinal, const RunBrush* brush) {
  if (path.kind == LineKind::Decal) return decal_style(decals_.at(path.decal), path, run);
  if (path.kind == LineKind::Hatching) {  // Kalnins et al. 2002, §6: faded and thickened by its level of detail
    StrokeStyle style = decal_style(decals_.at(path.decal), path, run);
    style.alpha = float(style.alpha * path.alpha_scale);
    style.width_px = float(style.width_px * path.width_scale);
    return style;
  }
  StrokeStyle style = line_style(path.kind, styles_);
  const std::vector<OffsetExample>& drawn = drawn_examples(path.kind, styles_);
  switch (run_offsets(path.kind, styles_)) {
    case RunOffsets::None:
    case RunOffsets::Own:
      return style;
    case RunOffsets::Drawn: {  // the stamp: in turn along the path, from the one the path's key picks
      double start = CounterStream(stream_key({seed_, path.key, kStampStart})).uniform();
      style.offsets = drawn[(size_t(start * double(drawn.size())) + ordinal) % drawn.size()];
      return style;
    }
    case RunOffsets::Synthesized:
      break;
  }
  auto it = chains_.find(path.kind);
  if (it == chains_.end()) it = chains_.emplace(path.kind, offset_chain(path.kind, styles_)).first;
  if (brush && path.kind == LineKind::Silhouette) {  // its brush path's, along t (Kalnins et al. 2003)
    CounterStream walk(brush_path_key(*brush, seed_, path, ordinal));
    style.offsets = it->second.synthesize_period(kBrushOffsetPeriodPx, walk);
  } else {
    style.offsets =
        it->second.synthesize_example(run.s1 - run.s0, CounterStream(brush_path_key({}, seed_, path, ordinal)));
  }
  return style;
}

std::vector<uint32_t> run_ordinals(const std::vector<VisibleRun>& runs) {
  std::map<uint32_t, uint32_t> seen;  // per path
  std::vector<uint32_t> out;
  for (const VisibleRun& run : runs) out.push_back(seen[run.path]++);
  return out;
}

std::vector<StrokeStyle> run_styles(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                    uint32_t seed, const std::vector<RunBrush>& brushes) {
  std::vector<StrokeStyle> out;
  RunStyles of_run(styles, seed, lines.decal_styles);
  std::vector<uint32_t> ordinals = run_ordinals(visibility.runs);
  for (size_t i = 0; i < visibility.runs.size(); ++i)
    out.push_back(of_run.of(lines.paths[visibility.runs[i].path], visibility.runs[i], ordinals[i],
                            i < brushes.size() ? &brushes[i] : nullptr));
  return out;
}

std::vector<StyledRun> styled_runs(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                   uint32_t seed, const std::vector<RunBrush>& brushes) {
  std::vector<StyledRun> out;
  std::vector<StrokeStyle> of_run = run_styles(lines, visibility, styles, seed, brushes);
  for (size_t i = 0; i < visibility.runs.size(); ++i) {
    const VisibleRun& run = visibility.runs[i];
    BrushParameter knots = i < brushes.size() ? brushes[i].knots : BrushParameter{};
    out.push_back(
        {{run.window, run.closed, run.occluded_start, run.occluded_end, std::move(knots)}, std::move(of_run[i])});
  }
  return out;
}

std::vector<RunStroke> run_strokes(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                   uint32_t seed, const std::vector<RunBrush>& brushes) {
  check_stroke_memory(lines, visibility, styles);
  std::vector<RunStroke> out;
  for (StyledRun& r : styled_runs(lines, visibility, styles, seed, brushes))
    out.push_back({r.style, base_stroke_samples(r.run, r.style)});
  return out;
}

std::vector<StrokeVertex> stroke_triangles(const WindowLines& lines, const Visibility& visibility,
                                           const StrokeStyles& styles, uint32_t seed) {
  return stroke_triangles(run_strokes(lines, visibility, styles, seed));
}

std::vector<StrokeVertex> stroke_triangles(const std::vector<RunStroke>& strokes) {
  std::vector<StrokeVertex> out;
  for (const RunStroke& stroke : strokes) {
    Ribbon r = ribbon(stroke.samples, stroke.style);
    for (const RibbonVertex& v : r.triangles)
      out.push_back({v.position, v.uv, v.alpha, r.color, float(int(stroke.style.texture))});
  }
  return out;
}

std::map<std::string, double> stroke_counts(const WindowLines* lines, const Visibility* v) {
  std::map<std::string, double> out;
  if (!v || !lines) return out;
  out["strokes"] = double(v->runs.size());
  out["paths"] = double(lines->paths.size());
  out["samples"] = double(v->samples);
  for (const VisibleRun& run : v->runs) out[std::string("strokes.") + line_kind_name(lines->paths[run.path].kind)] += 1;
  for (const HatchGroupState& g : lines->hatching) {
    std::string name = "hatching.group" + std::to_string(g.number);
    out[name + ".sigma"] = g.sigma;
    out[name + ".level"] = g.lod.from + g.progress * (g.lod.to - g.lod.from);
  }
  return out;
}

std::vector<Image> stroke_texture_layers(uint32_t seed) {
  std::vector<Image> layers;
  for (size_t k = 0; k < stroke_texture_names().size(); ++k)
    layers.push_back(stroke_texture(StrokeTextureKind(k), seed));
  return layers;
}

}  // namespace plumbago
