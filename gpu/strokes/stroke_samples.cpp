// Stroke samples on the GPU: see gpu/strokes/stroke_samples.hpp.
#include "gpu/strokes/stroke_samples.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

Program step(const char* name) {
  return Program::compute("strokes/stroke_samples.comp", std::string("#define ") + name + "\n");
}

enum RunFlags : uint32_t {
  kClosed = 1,
  kOccludedStart = 2,
  kOccludedEnd = 4,
  kPressureWidth = 8,
  kPressureAlpha = 16,
  kRepeats = 32
};  // stroke_samples.comp's

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

uint32_t flags(const StrokeRun& r, const StrokeStyle& s) {
  return (r.closed ? kClosed : 0u) | (r.occluded_start ? kOccludedStart : 0u) | (r.occluded_end ? kOccludedEnd : 0u) |
         (s.pressure_width ? kPressureWidth : 0u) | (s.pressure_alpha ? kPressureAlpha : 0u) |
         (s.offsets && s.offsets->repeats ? kRepeats : 0u);
}

}  // namespace

// The tables stroke_samples.comp reads: per run its style and where its points are (made
// on the GPU from the run tables: there), the styles' offsets, and the bounds the buffers
// are sized by.
struct StrokeSamples::Inputs {
  explicit Inputs(const std::vector<StyledRun>& runs) {
    for (const StyledRun& r : runs) {
      add(r.run, r.style, polyline_length(r.run));
      runs_in.back().first_point = uint32_t(points.size()), runs_in.back().point_count = uint32_t(r.run.points.size());
      points.insert(points.end(), r.run.points.begin(), r.run.points.end());
    }
    point_bound = double(points.size());
  }
  // The polyline of a run along path p has at most its points and the two ends, and the runs
  // of a path do not overlap: each path point lies in one at most.
  Inputs(const WindowLines& lines, const Visibility& visibility, const std::vector<StrokeStyle>& styles) {
    std::vector<bool> has_run(lines.paths.size(), false);
    for (size_t i = 0; i < visibility.runs.size(); ++i) {
      const VisibleRun& r = visibility.runs[i];
      const WindowPath& path = lines.paths.at(r.path);
      add({{}, r.closed, r.occluded_start, r.occluded_end}, styles.at(i), r.closed ? path.length_px : r.s1 - r.s0);
      point_bound += has_run[r.path] ? 2.0 : 2.0 + double(path.window.size());
      has_run[r.path] = true;
    }
  }
  std::vector<RunInput> runs_in;
  std::vector<glm::dvec2> points;  // the polylines given
  std::vector<OffsetInput> offsets;
  double bound = 0, point_bound = 0;

 private:
  void add(const StrokeRun& run, const StrokeStyle& s, double length) {
    const auto& example = s.offsets;
    runs_in.push_back({glm::vec4(s.color_r, s.color_g, s.color_b, float(int(s.texture))), 0, 0,
                       uint32_t(offsets.size()), uint32_t(example ? example->offsets.size() : 0),
                       example ? example->length_px : 0.0, s.width_px, s.alpha, s.taper_px, s.fade_px, s.halo_px,
                       s.flare, s.sample_px, s.texture_period_px, flags(run, s)});
    if (example)
      for (const StrokeOffset& o : example->offsets)
        offsets.push_back({o.t, o.displacement_px, o.pressure, o.pen_up ? 1u : 0u});
    bound += sample_bound(length, s);
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

double sample_bound(double polyline_length, const StrokeStyle& style) {
  // |v_i| <= 1 gives tangents of at most the chord d (3 d at an open end's parabolic slope), so
  // each span's control polygon, which its curve and the dense polyline do not exceed, is at
  // most d + 2 (|m0| + |m1|) / 3 <= 11 d / 3; a little more for rounding.
  double length = polyline_length * (11.0 / 3.0) * (1 + 1e-9) + 1e-6;
  double even = std::floor(length / style.sample_px) + 3;  // n + 1 samples, n = ceil(L / sample_px)
  const auto& example = style.offsets;
  if (!example) return even;
  auto lifts = double(
      std::count_if(example->offsets.begin(), example->offsets.end(), [](const StrokeOffset& o) { return o.pen_up; }));
  return even + 2 * lifts * (std::floor(length / example->length_px) + 2);  // two changes a lift a period
}

double sample_bound(const StyledRun& r) { return sample_bound(polyline_length(r.run), r.style); }

StrokeSamples::StrokeSamples()
    : polyline_count_(step("STEP_POLYLINE_COUNT")),
      polyline_write_(step("STEP_POLYLINE_WRITE")),
      count_(step("STEP_COUNT")),
      write_(step("STEP_WRITE")),
      args_(step("STEP_ARGS")) {}

void StrokeSamples::operator()(const std::vector<StyledRun>& runs) { run(Inputs(runs), nullptr); }

void StrokeSamples::operator()(const WindowLines& lines, const Visibility& visibility,
                               const std::vector<StrokeStyle>& styles, const RunTables& tables) {
  if (tables.count != visibility.runs.size())
    throw std::logic_error("stroke samples: the GPU lists " + std::to_string(tables.count) + " runs, not " +
                           std::to_string(visibility.runs.size()));
  run(Inputs(lines, visibility, styles), &tables);
}

void StrokeSamples::run(const Inputs& in, const RunTables* tables) {
  runs_ = uint32_t(in.runs_in.size());
  if (runs_ == 0) return;
  check_memory(runs_, in.bound, in.point_bound);
  capacity_ = uint32_t(std::max(in.bound, 1.0));
  const auto points = size_t(in.point_bound);
  runs_in_ = make_buffer(in.runs_in.data(), in.runs_in.size() * sizeof(RunInput));
  points_ = make_buffer(tables ? nullptr : in.points.data(), points * sizeof(glm::dvec2));
  offsets_ = make_buffer(in.offsets.data(), in.offsets.size() * sizeof(OffsetInput));
  counts_ = make_zeroed_buffer(runs_ + 1);
  distinct_ = make_buffer(nullptr, points * sizeof(glm::dvec2));
  states_ = make_buffer(nullptr, runs_ * sizeof(RunState));
  bases_ = make_buffer(nullptr, size_t(capacity_) * sizeof(BaseRecord));
  samples_ = make_buffer(nullptr, size_t(capacity_) * sizeof(SampleRecord));
  runs_out_ = make_buffer(nullptr, runs_ * sizeof(RunRecord));
  draw_ = make_buffer(nullptr, 4 * sizeof(uint32_t));
  for (const Program* p : {&polyline_count_, &polyline_write_, &count_, &write_, &args_}) {
    glProgramUniform1ui(p->id(), p->uniform("run_count"), runs_);
    glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity_);
  }
  auto bind_all = [&] {
    const Buffer* at[] = {&samples_, &runs_out_, &runs_in_, &points_, &offsets_,
                          &counts_,  &distinct_, &states_,  &draw_,   &bases_};
    for (GLuint k = 0; k < 10; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  };
  bind_all();
  if (tables) make_polylines(*tables);
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

// 0. Each run's polyline from its path (stroke_samples.comp STEP_POLYLINE_*), placed by a
// prefix sum over their counts, written into points_ and the runs' records.
void StrokeSamples::make_polylines(const RunTables& tables) {
  const Buffer* at[] = {tables.paths, tables.points, tables.runs};
  for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10 + k, at[k]->id());
  dispatch_in_chunks(polyline_count_, runs_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(counts_, size_t(runs_) + 1);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, runs_in_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, points_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, counts_.id());
  for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10 + k, at[k]->id());
  dispatch_in_chunks(polyline_write_, runs_, "first");
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
