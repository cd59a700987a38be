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

uint32_t flags(const StyledRun& r) {
  return (r.run.closed ? kClosed : 0u) | (r.run.occluded_start ? kOccludedStart : 0u) |
         (r.run.occluded_end ? kOccludedEnd : 0u) | (r.style.pressure_width ? kPressureWidth : 0u) |
         (r.style.pressure_alpha ? kPressureAlpha : 0u) | (r.style.offsets && r.style.offsets->repeats ? kRepeats : 0u);
}

// The tables stroke_samples.comp reads.
struct Inputs {
  explicit Inputs(const std::vector<StyledRun>& runs) {
    for (const StyledRun& r : runs) {
      const StrokeStyle& s = r.style;
      const auto& example = s.offsets;
      runs_in.push_back({glm::vec4(s.color_r, s.color_g, s.color_b, float(int(s.texture))), uint32_t(points.size()),
                         uint32_t(r.run.points.size()), uint32_t(offsets.size()),
                         uint32_t(example ? example->offsets.size() : 0), example ? example->length_px : 0.0,
                         s.width_px, s.alpha, s.taper_px, s.fade_px, s.halo_px, s.flare, s.sample_px,
                         s.texture_period_px, flags(r)});
      points.insert(points.end(), r.run.points.begin(), r.run.points.end());
      if (example)
        for (const StrokeOffset& o : example->offsets)
          offsets.push_back({o.t, o.displacement_px, o.pressure, o.pen_up ? 1u : 0u});
      bound += sample_bound(r);
    }
  }
  std::vector<RunInput> runs_in;
  std::vector<glm::dvec2> points;
  std::vector<OffsetInput> offsets;
  double bound = 0;
};

// The scratch records of stroke_samples.comp (std430): per sample, per run.
struct BaseRecord {
  glm::dvec2 point, normal;
  double s, pad;
};
struct RunState {
  double length;
  uint32_t distinct_count, pad;
};

// Every buffer of at least 16 bytes: GL refuses a binding of none. `data` (when given) holds
// `bytes`.
Buffer upload(const void* data, size_t bytes) {
  if (bytes >= 16) return make_buffer(data, bytes);
  std::vector<unsigned char> padded(16, 0);
  if (data) std::copy_n(static_cast<const unsigned char*>(data), bytes, padded.begin());
  return make_buffer(padded.data(), padded.size());
}

void check_memory(size_t runs, double bound) {
  char what[160];
  std::snprintf(what, sizeof what, "the stroke samples of %zu visible runs on the GPU (at most %.0f)", runs, bound);
  check_memory_budget(what, bound * double(sizeof(SampleRecord) + sizeof(BaseRecord)));
  if (bound > double(std::numeric_limits<uint32_t>::max() / 8))
    throw std::length_error(std::string(what) + ": more than 2^29 samples");
}

}  // namespace

double sample_bound(const StyledRun& r) {
  // |v_i| <= 1 gives tangents of at most the chord d (3 d at an open end's parabolic slope), so
  // each span's control polygon, which its curve and the dense polyline do not exceed, is at
  // most d + 2 (|m0| + |m1|) / 3 <= 11 d / 3; a little more for rounding.
  double length = polyline_length(r.run) * (11.0 / 3.0) * (1 + 1e-9) + 1e-6;
  double even = std::floor(length / r.style.sample_px) + 3;  // n + 1 samples, n = ceil(L / sample_px)
  const auto& example = r.style.offsets;
  if (!example) return even;
  auto lifts = double(
      std::count_if(example->offsets.begin(), example->offsets.end(), [](const StrokeOffset& o) { return o.pen_up; }));
  return even + 2 * lifts * (std::floor(length / example->length_px) + 2);  // two changes a lift a period
}

StrokeSamples::StrokeSamples() : count_(step("STEP_COUNT")), write_(step("STEP_WRITE")), args_(step("STEP_ARGS")) {}

void StrokeSamples::operator()(const std::vector<StyledRun>& runs) {
  runs_ = uint32_t(runs.size());
  if (runs.empty()) return;
  Inputs in(runs);
  check_memory(runs.size(), in.bound);
  capacity_ = uint32_t(std::max(in.bound, 1.0));
  runs_in_ = upload(in.runs_in.data(), in.runs_in.size() * sizeof(RunInput));
  points_ = upload(in.points.data(), in.points.size() * sizeof(glm::dvec2));
  offsets_ = upload(in.offsets.data(), in.offsets.size() * sizeof(OffsetInput));
  counts_ = make_zeroed_buffer(runs.size() + 1);
  distinct_ = upload(nullptr, in.points.size() * sizeof(glm::dvec2));
  states_ = upload(nullptr, runs.size() * sizeof(RunState));
  bases_ = upload(nullptr, size_t(capacity_) * sizeof(BaseRecord));
  samples_ = upload(nullptr, size_t(capacity_) * sizeof(SampleRecord));
  runs_out_ = upload(nullptr, runs.size() * sizeof(RunRecord));
  draw_ = upload(nullptr, 4 * sizeof(uint32_t));
  for (const Program* p : {&count_, &write_, &args_}) {
    glProgramUniform1ui(p->id(), p->uniform("run_count"), runs_);
    glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity_);
  }
  auto bind_all = [&] {
    const Buffer* at[] = {&samples_, &runs_out_, &runs_in_, &points_, &offsets_,
                          &counts_,  &distinct_, &states_,  &draw_,   &bases_};
    for (GLuint k = 0; k < 10; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  };
  bind_all();
  dispatch_in_chunks(count_, runs_, "first");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(counts_, runs.size() + 1);
  bind_all();
  dispatch_in_chunks(write_, runs_, "first");
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
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
