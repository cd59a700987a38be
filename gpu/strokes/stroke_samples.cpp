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
         (example && example->repeats ? kRepeats : 0u);
}

}  // namespace

// The tables stroke_samples.comp reads, given (per run its style and points, the styles'
// offsets), or made on the GPU from the run tables (run_inputs.comp: there), and the bounds
// the buffers are sized by.
struct StrokeSamples::Inputs {
  explicit Inputs(const std::vector<StyledRun>& runs) {
    for (const StyledRun& r : runs) {
      add(r.run, r.style, polyline_length(r.run));
      runs_in.back().first_point = uint32_t(points.size()), runs_in.back().point_count = uint32_t(r.run.points.size());
      points.insert(points.end(), r.run.points.begin(), r.run.points.end());
    }
    point_bound = double(points.size()), this->runs = runs.size();
  }
  // The polyline of a run along path p has at most its points and the two ends, and the runs
  // of a path do not overlap: each path point lies in one at most; so has a decal's pressure
  // example.
  Inputs(const WindowLines& lines, const Visibility& visibility, const RunStyleTables& styles)
      : offsets(styles.offsets()), runs(visibility.runs.size()) {
    std::vector<bool> has_run(lines.paths.size(), false);
    double made = 0;  // offsets the runs make
    for (const VisibleRun& r : visibility.runs) {
      const WindowPath& path = lines.paths.at(r.path);
      const uint32_t style = PathTable::style_of(path);
      const double length = r.closed ? path.length_px : r.s1 - r.s0,
                   points = has_run[r.path] ? 2.0 : 2.0 + double(path.window.size());
      bound += styles.sample_bound(style, length);
      point_bound += points;
      made += styles.decal(style) ? points : styles.synthesized_offsets(style, length);
      has_run[r.path] = true;
    }
    offsets.resize(offsets.size() + size_t(made));
  }
  std::vector<RunInput> runs_in;   // given
  std::vector<glm::dvec2> points;  // given
  std::vector<OffsetInput> offsets;
  size_t runs = 0;
  double bound = 0, point_bound = 0;

 private:
  void add(const StrokeRun& run, const StrokeStyle& s, double length) {
    const auto& example = s.offsets;
    RunInput in{};
    put_style(s, in);
    in.flags |= flags(run, example);
    in.first_offset = uint32_t(offsets.size()), in.offset_count = uint32_t(example ? example->offsets.size() : 0);
    in.example_length = example ? example->length_px : 0.0;
    runs_in.push_back(in);
    if (example)
      for (const StrokeOffset& o : example->offsets) offsets.push_back(offset_input(o));
    bound += sample_bound(length, s.sample_px, example ? example->length_px : 0.0, example ? pen_lifts(*example) : 0.0);
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

}  // namespace

double pen_lifts(const OffsetExample& e) {
  return double(std::count_if(e.offsets.begin(), e.offsets.end(), [](const StrokeOffset& o) { return o.pen_up; }));
}

double sample_bound(double polyline_length, double sample_px, double example_length, double lifts) {
  // |v_i| <= 1 gives tangents of at most the chord d (3 d at an open end's parabolic slope), so
  // each span's control polygon, which its curve and the dense polyline do not exceed, is at
  // most d + 2 (|m0| + |m1|) / 3 <= 11 d / 3; a little more for rounding.
  double length = polyline_length * (11.0 / 3.0) * (1 + 1e-9) + 1e-6;
  double even = std::floor(length / sample_px) + 3;  // n + 1 samples, n = ceil(L / sample_px)
  if (lifts == 0) return even;
  return even + 2 * lifts * (std::floor(length / example_length) + 2);  // two changes a lift a period
}

double sample_bound(const StyledRun& r) {
  const auto& e = r.style.offsets;
  return sample_bound(polyline_length(r.run), r.style.sample_px, e ? e->length_px : 0.0, e ? pen_lifts(*e) : 0.0);
}

StrokeSamples::StrokeSamples()
    : inputs_count_(step("run_inputs", "STEP_COUNT")),
      inputs_write_(step("run_inputs", "STEP_WRITE")),
      count_(step("stroke_samples", "STEP_COUNT")),
      write_(step("stroke_samples", "STEP_WRITE")),
      args_(step("stroke_samples", "STEP_ARGS")) {}

void StrokeSamples::operator()(const std::vector<StyledRun>& runs) { run(Inputs(runs), nullptr, nullptr); }

void StrokeSamples::operator()(const WindowLines& lines, const Visibility& visibility, const RunTables& tables,
                               const RunStyleTables& styles, uint32_t seed) {
  if (tables.count != visibility.runs.size())
    throw std::logic_error("stroke samples: the GPU lists " + std::to_string(tables.count) + " runs, not " +
                           std::to_string(visibility.runs.size()));
  glProgramUniform1ui(inputs_write_.id(), inputs_write_.uniform("seed"), seed);
  glProgramUniform1ui(inputs_write_.id(), inputs_write_.uniform("own_offsets"), styles.own_offsets());
  glProgramUniform1ui(inputs_count_.id(), inputs_count_.uniform("seed"), seed);
  run(Inputs(lines, visibility, styles), &tables, &styles);
}

void StrokeSamples::run(const Inputs& in, const RunTables* tables, const RunStyleTables* styles) {
  runs_ = uint32_t(in.runs);
  if (runs_ == 0) return;
  check_memory(runs_, in.bound, in.point_bound);
  capacity_ = uint32_t(std::max(in.bound, 1.0));
  const auto points = size_t(in.point_bound);
  runs_in_ = make_buffer(tables ? nullptr : in.runs_in.data(), runs_ * sizeof(RunInput));
  points_ = make_buffer(tables ? nullptr : in.points.data(), points * sizeof(glm::dvec2));
  offsets_ = make_buffer(in.offsets.data(), in.offsets.size() * sizeof(OffsetInput));
  counts_ = make_zeroed_buffer(runs_ + 1);
  distinct_ = make_buffer(nullptr, points * sizeof(glm::dvec2));
  states_ = make_buffer(nullptr, runs_ * sizeof(RunState));
  bases_ = make_buffer(nullptr, size_t(capacity_) * sizeof(BaseRecord));
  samples_ = make_buffer(nullptr, size_t(capacity_) * sizeof(SampleRecord));
  runs_out_ = make_buffer(nullptr, runs_ * sizeof(RunRecord));
  draw_ = make_buffer(nullptr, 4 * sizeof(uint32_t));
  for (const Program* p : {&inputs_count_, &inputs_write_, &count_, &write_, &args_}) {
    glProgramUniform1ui(p->id(), p->uniform("run_count"), runs_);
    glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity_);
  }
  auto bind_all = [&] {
    const Buffer* at[] = {&samples_, &runs_out_, &runs_in_, &points_, &offsets_,
                          &counts_,  &distinct_, &states_,  &draw_,   &bases_};
    for (GLuint k = 0; k < 10; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  };
  if (tables) make_inputs(*tables, *styles);
  bind_all();
  dispatch_in_chunks(count_, runs_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(counts_, size_t(runs_) + 1);
  bind_all();
  dispatch_in_chunks(write_, runs_, "first");
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

// 0. Each run's polyline and style (run_inputs.comp): its points and the offsets it makes
// counted, placed by prefix sums, written into points_, offsets_ and runs_in_.
void StrokeSamples::make_inputs(const RunTables& tables, const RunStyleTables& styles) {
  Buffer point_counts = make_zeroed_buffer(size_t(runs_) + 1), offset_counts = make_zeroed_buffer(size_t(runs_) + 1);
  auto bind_all = [&] {
    const Buffer* at[] = {tables.paths, tables.points, tables.runs};
    for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
    styles.bind();
    const Buffer* out[] = {&point_counts, &offset_counts, &runs_in_, &points_, &offsets_};
    for (GLuint k = 0; k < 5; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7 + k, out[k]->id());
  };
  bind_all();
  dispatch_in_chunks(inputs_count_, runs_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(point_counts, size_t(runs_) + 1);
  scan_(offset_counts, size_t(runs_) + 1);
  bind_all();
  dispatch_in_chunks(inputs_write_, runs_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

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
