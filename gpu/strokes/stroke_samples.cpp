// Stroke samples on the GPU: see gpu/strokes/stroke_samples.hpp.
#include "gpu/strokes/stroke_samples.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

Program step(const char* file, const char* name) {
  return Program::compute(std::string("strokes/") + file + ".comp", std::string("#define ") + name + "\n");
}

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The length of the polyline through a run's finite points (around the loop when closed).
double polyline_length(const StrokeRun& run) {
  double length = 0;
  const glm::dvec2 *first = nullptr, *last = nullptr;
  for (const glm::dvec2& p : run.points) {
    if (!finite(p)) continue;
    if (last) length += glm::distance(*last, p);
    if (!first) first = &p;
    last = &p;
  }
  return run.closed && first ? length + glm::distance(*last, *first) : length;
}

// A run's own flags (its style's are put_style's).
uint32_t flags(const StrokeRun& r, const std::optional<OffsetExample>& example) {
  return (r.closed ? kClosed : 0u) | (r.occluded_start ? kOccludedStart : 0u) | (r.occluded_end ? kOccludedEnd : 0u) |
         (example && example->repeats ? kRepeats : 0u) | (example && !example->scales ? kUnscaled : 0u);
}

}  // namespace

// The tables stroke_samples.comp reads, given (per run its style and points, the styles'
// offsets), or made on the GPU from the run tables (run_inputs.comp: there), and the bounds
// the buffers are sized by.
struct StrokeSamples::Inputs : Sizes {
  explicit Inputs(const Sizes& sizes) : Sizes(sizes) {}
  explicit Inputs(const std::vector<StyledRun>& runs) {
    for (const StyledRun& r : runs) {
      add(r.run, r.style);
      RunInput& in = runs_in.back();
      in.first_point = uint32_t(points.size()), in.point_count = uint32_t(r.run.points.size());
      in.knot_count = r.run.brush.size() >= 2 ? uint32_t(r.run.brush.size()) : 0u;
      points.insert(points.end(), r.run.points.begin(), r.run.points.end());
      points.insert(points.end(), r.run.brush.begin(), r.run.brush.begin() + in.knot_count);
    }
    point_bound = double(points.size()), this->runs = runs.size(), offset_rows = offsets.size();
  }
  // From the paths' run bounds alone (window_paths.hpp RunBound): a path's runs do not overlap.
  Inputs(const RunTables& tables, const RunStyleTables& styles) {
    double made = 0, rows = 0;  // offsets the runs make; most runs
    offset_rows = styles.own_offsets();
    for (const RunBound& b : tables.bounds) {
      if (b.runs == 0) continue;
      rows += b.runs;
      bound += styles.sample_bound(b.style, b.length, b.runs);
      point_bound += b.points;
      made += styles.decal(b.style) ? b.points : styles.synthesized_offsets(b.style, b.length, b.runs);
    }
    offset_rows += size_t(made);  // the examples' own copied on the GPU, the rest made there
    runs = std::min(size_t(tables.bound), size_t(std::ceil(rows)));
  }
  std::vector<RunInput> runs_in;     // given
  std::vector<glm::dvec2> points;    // given
  std::vector<OffsetInput> offsets;  // given

 private:
  void add(const StrokeRun& run, const StrokeStyle& s) {
    const auto& example = s.offsets;
    RunInput in{};
    put_style(s, in);
    in.flags |= flags(run, example);
    in.first_offset = uint32_t(offsets.size()), in.offset_count = uint32_t(example ? example->offsets.size() : 0);
    in.example_length = example ? example->length_px : 0.0;
    runs_in.push_back(in);
    if (example)
      for (const StrokeOffset& o : example->offsets) offsets.push_back(offset_input(o));
    bound += sample_bound(StyledRun{run, s});
  }
};

namespace {

// The scratch records of stroke_samples.comp (std430): per sample, per run.
struct BaseRecord {
  glm::dvec2 point, normal;
  double s, pad;
};
struct RunState {
  double length;
  uint32_t distinct_count, pad;
};

void check_memory(size_t runs, double bound, double points) {
  char what[160];
  std::snprintf(what, sizeof what, "the stroke samples of %zu visible runs on the GPU (at most %.0f)", runs, bound);
  check_memory_budget(
      what, bound * double(sizeof(SampleRecord) + sizeof(BaseRecord)) + points * double(2 * sizeof(glm::dvec2)));
  if (bound > double(std::numeric_limits<uint32_t>::max() / 8) || points > double(std::numeric_limits<uint32_t>::max()))
    throw std::length_error(std::string(what) + ": more than 2^29 samples or 2^32 points");
}

// How far t runs over polyline arc lengths [0, P] (the first and last intervals extended,
// brush_t's): the sum over its pieces of |dt/ds| times their part of [0, P].
double brush_variation(const BrushParameter& k, double P) {
  double v = 0;
  for (size_t i = 0; i + 1 < k.size(); ++i) {
    double from = i == 0 ? 0.0 : std::max(0.0, k[i].x), to = i + 2 == k.size() ? P : std::min(P, k[i + 1].x);
    if (k[i + 1].x > k[i].x && to > from) v += std::abs(k[i + 1].y - k[i].y) / (k[i + 1].x - k[i].x) * (to - from);
  }
  return v;
}

}  // namespace

double pen_lifts(const OffsetExample& e) {
  return double(std::count_if(e.offsets.begin(), e.offsets.end(), [](const StrokeOffset& o) { return o.pen_up; }));
}

double sample_bound(double polyline_length, double runs, double sample_px, double example_length, double lifts) {
  // |v_i| <= 1 gives tangents of at most the chord d (3 d at an open end's parabolic slope), so
  // each span's control polygon, which its curve and the dense polyline do not exceed, is at
  // most d + 2 (|m0| + |m1|) / 3 <= 11 d / 3; a little more for rounding.
  double length = polyline_length * (11.0 / 3.0) * (1 + 1e-9) + 1e-6 * runs;
  double even = std::floor(length / sample_px) + 3 * runs;  // n + 1 samples a run, n = ceil(L / sample_px)
  if (lifts == 0) return even;
  return even + 2 * lifts * (std::floor(length / example_length) + 2 * runs);  // two changes a lift a period
}

double sample_bound(const StyledRun& r) {
  const auto& e = r.style.offsets;
  double length = polyline_length(r.run), lifts = e ? pen_lifts(*e) : 0.0;
  if (!e || !e->repeats || r.run.brush.size() < 2)
    return sample_bound(length, 1, r.style.sample_px, e ? e->length_px : 0.0, lifts);
  // Stamped along the brush parameter: each of its pieces walks the periods its t spans, and
  // one or two more at either end.
  double pieces = double(r.run.brush.size() - 1);
  double periods = std::floor(brush_variation(r.run.brush, length * (1 + 1e-9) + 1e-6) / e->length_px) + 3 * pieces;
  return sample_bound(length, 1, r.style.sample_px, 0.0, 0.0) + 2 * lifts * periods;
}

StrokeSamples::StrokeSamples()
    : inputs_args_(step("run_inputs", "STEP_ARGS")),
      inputs_count_(step("run_inputs", "STEP_COUNT")),
      inputs_write_(step("run_inputs", "STEP_WRITE")),
      knots_count_(step("run_knots", "STEP_COUNT")),
      knots_copy_(step("run_knots", "STEP_COPY")),
      count_(step("stroke_samples", "STEP_COUNT")),
      write_(step("stroke_samples", "STEP_WRITE")),
      args_(step("stroke_samples", "STEP_ARGS")) {}

void StrokeSamples::operator()(const std::vector<StyledRun>& runs) { run(Inputs(runs), nullptr, nullptr, nullptr); }

void StrokeSamples::operator()(const RunTables& tables, const RunStyleTables& styles, uint32_t seed,
                               const BrushFit* brushes, bool coherent) {
  coherent = coherent || brushes;
  for (const Program* p : {&inputs_args_, &inputs_count_, &inputs_write_}) {
    glProgramUniform1ui(p->id(), p->uniform("seed"), seed);
    glProgramUniform1ui(p->id(), p->uniform("own_offsets"), styles.own_offsets());
    glProgramUniform1ui(p->id(), p->uniform("listed_at"), tables.listed.at);
    glProgramUniform1ui(p->id(), p->uniform("coherent_silhouettes"), coherent ? 1u : 0u);
    glProgramUniform1ui(p->id(), p->uniform("with_fit"), brushes ? 1u : 0u);
    glProgramUniform1f(p->id(), p->uniform("brush_period_px"), float(kBrushOffsetPeriodPx));
  }
  if (tables.sized) sized_ = Inputs(tables, styles);
  Inputs in(sized_);
  if (brushes) in.point_bound += brushes->knot_capacity();  // each run's knots after its points
  run(in, &tables, &styles, brushes);
}

void StrokeSamples::run(const Inputs& in, const RunTables* tables, const RunStyleTables* styles,
                        const BrushFit* brushes) {
  runs_ = uint32_t(in.runs);
  if (runs_ == 0) return;
  check_memory(runs_, in.bound, in.point_bound);
  capacity_ = uint32_t(std::max(in.bound, 1.0));
  const auto points = size_t(in.point_bound);
  if (tables) {  // made on the GPU
    runs_in_.reserve(runs_ * sizeof(RunInput)), points_.reserve(points * sizeof(glm::dvec2));
    offsets_.reserve(in.offset_rows * sizeof(OffsetInput));
  } else {
    runs_in_ = {make_buffer(in.runs_in.data(), runs_ * sizeof(RunInput)), runs_ * sizeof(RunInput)};
    points_ = {make_buffer(in.points.data(), points * sizeof(glm::dvec2)), points * sizeof(glm::dvec2)};
    offsets_ = {make_buffer(in.offsets.data(), in.offset_rows * sizeof(OffsetInput)),
                in.offset_rows * sizeof(OffsetInput)};
  }
  counts_.reserve((size_t(runs_) + 1) * sizeof(uint32_t));
  distinct_.reserve(points * sizeof(glm::dvec2)), states_.reserve(runs_ * sizeof(RunState));
  bases_.reserve(size_t(capacity_) * sizeof(BaseRecord)), samples_.reserve(size_t(capacity_) * sizeof(SampleRecord));
  runs_out_.reserve(runs_ * sizeof(RunRecord)), draw_.reserve(4 * sizeof(uint32_t));
  const uint32_t given[4] = {std::clamp((runs_ + 63) / 64, 1u, 65535u), 1, 1, runs_};  // the GPU's: run_inputs.comp
  run_args_ = make_buffer(tables ? nullptr : given, sizeof given);
  for (const Program* p : {&inputs_args_, &inputs_count_, &inputs_write_, &count_, &write_, &args_}) {
    glProgramUniform1ui(p->id(), p->uniform("run_count"), runs_);
    glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity_);
    glProgramUniform1ui(p->id(), p->uniform("point_capacity"), GLuint(points_.bytes / sizeof(glm::dvec2)));
    glProgramUniform1ui(p->id(), p->uniform("offset_capacity"), GLuint(offsets_.bytes / sizeof(OffsetInput)));
  }
  auto bind_all = [&] {
    const Buffer* at[] = {&samples_.buffer, &runs_out_.buffer, &runs_in_.buffer,  &points_.buffer,
                          &offsets_.buffer, &counts_.buffer,   &distinct_.buffer, &states_.buffer,
                          &draw_.buffer,    &bases_.buffer,    &run_args_};
    for (GLuint k = 0; k < 11; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  };
  if (tables) make_inputs(*tables, *styles, brushes);
  bind_all();
  over_runs(count_);
  scan_(counts_, size_t(runs_) + 1, run_args_, 3, 1);  // over the runs listed
  bind_all();
  over_runs(write_);
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

// 0. Each run's polyline and style (run_inputs.comp): its points and the offsets it makes
// counted, placed by prefix sums, written into points_, offsets_ and runs_in_.
void StrokeSamples::make_inputs(const RunTables& tables, const RunStyleTables& styles, const BrushFit* brushes) {
  styles.copy_offsets(offsets_);
  point_counts_.reserve((size_t(runs_) + 1) * sizeof(uint32_t));
  offset_counts_.reserve((size_t(runs_) + 1) * sizeof(uint32_t));
  auto bind_all = [&] {
    const Buffer* at[] = {tables.paths, tables.points, tables.runs};
    for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
    styles.bind();
    const Buffer* out[] = {&point_counts_.buffer,
                           &offset_counts_.buffer,
                           &runs_in_.buffer,
                           &points_.buffer,
                           &offsets_.buffer,
                           tables.listed.buffer,
                           &run_args_,
                           brushes ? &brushes->runs_buffer() : &run_args_};
    for (GLuint k = 0; k < 8; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7 + k, out[k]->id());
  };
  bind_all();
  glUseProgram(inputs_args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  over_runs(inputs_count_);
  if (brushes) over_knots(knots_count_, *brushes);
  scan_(point_counts_, size_t(runs_) + 1, run_args_, 3, 1);
  scan_(offset_counts_, size_t(runs_) + 1, run_args_, 3, 1);
  bind_all();
  over_runs(inputs_write_);
  if (brushes) over_knots(knots_copy_, *brushes);
}

// A step of run_knots.comp over the runs listed: the fit's knots into the runs' inputs.
void StrokeSamples::over_knots(const Program& step, const BrushFit& brushes) const {
  const Buffer* at[] = {&brushes.runs_buffer(), &brushes.knots_buffer(), &point_counts_.buffer,
                        &runs_in_.buffer,       &points_.buffer,         &run_args_};
  for (GLuint k = 0; k < 6; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  over_runs(step);
}

// A step over the runs listed, dispatched as run_args_ says.
void StrokeSamples::over_runs(const Program& step) const { dispatch_indirect(step, run_args_); }

void StrokeSamples::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, samples_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, runs_out_.id());
}

std::vector<SampleRecord> StrokeSamples::samples() const {
  std::vector<SampleRecord> out(runs_ ? capacity_ : 0);
  if (!out.empty()) read_buffer(samples_, out.data(), out.size() * sizeof(SampleRecord));
  return out;
}

std::vector<RunRecord> StrokeSamples::runs() const {
  std::vector<RunRecord> out(runs_);
  if (!out.empty()) read_buffer(runs_out_, out.data(), out.size() * sizeof(RunRecord));
  return out;
}

}  // namespace plumbago::gpu
