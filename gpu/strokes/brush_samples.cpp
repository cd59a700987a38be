// The brush samples of coherent silhouettes on the GPU: see gpu/strokes/brush_samples.hpp.
#include "gpu/strokes/brush_samples.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/strokes/strokes.hpp"
#include "common/util/memory_budget.hpp"
#include "gpu/strokes/brush_fit.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_samples.comp (std430).
struct SampleRecord {
  double x, y, z, t;
  uint32_t stroke, path;
};
struct FrameRecord {
  glm::dmat4 clip, unclip, view, projection;
  double width, height, sample_px, pad = 0;
};
static_assert(sizeof(SampleRecord) == 40 && sizeof(FitRunRecord) == 32 && sizeof(FrameRecord) == 544,
              "std430 layouts of brush_samples.comp");

Program step(const char* name) {
  return Program::compute("strokes/brush_samples.comp", std::string("#define ") + name + "\n");
}

}  // namespace

BrushSamples::BrushSamples() : count_(step("STEP_COUNT")), write_(step("STEP_WRITE")) {}

void BrushSamples::operator()(const RunTables& tables, const Camera& camera, int width, int height,
                              const std::vector<RunBrush>& brushes, const CoherenceParams& p, uint32_t seed) {
  std::vector<FitRunRecord> runs;
  std::vector<glm::dvec2> knots;
  for (const RunBrush& b : brushes) {
    runs.push_back({0, 0, 0, uint32_t(knots.size()), uint32_t(b.knots.size()), b.path});
    knots.insert(knots.end(), b.knots.begin(), b.knots.end());
  }
  runs.resize(std::max<size_t>(tables.bound, 1), FitRunRecord{0, 0, 0, 0, 0});
  fit_runs_ = scratch_of(runs), knots_ = scratch_of(knots);
  sample(tables, camera, width, height, brushes.empty() ? nullptr : &fit_runs_.buffer, knots_, p, seed);
}

void BrushSamples::operator()(const RunTables& tables, const Camera& camera, int width, int height, const BrushFit* fit,
                              const CoherenceParams& p, uint32_t seed) {
  knots_.reserve(sizeof(glm::dvec2));
  sample(tables, camera, width, height, fit ? &fit->runs_buffer() : nullptr, fit ? fit->knots_buffer() : knots_, p,
         seed);
}

void BrushSamples::sample(const RunTables& tables, const Camera& camera, int width, int height, const Buffer* fit_runs,
                          const Buffer& knots, const CoherenceParams& p, uint32_t seed) {
  double bound = 1;  // n + 1 samples a run, n <= L / sample_px + 1
  for (const RunBound& b : tables.bounds) bound += b.length / p.sample_px + 2 * b.runs;
  check_memory_budget("the brush samples of " + std::to_string(tables.bound) + " runs on the GPU",
                      bound * double(sizeof(SampleRecord)));
  capacity_ = uint32_t(std::ceil(bound));
  WindowProjection project(camera, width, height);
  glm::dmat4 projection = glm::dmat4(camera.projection(float(width) / float(height)));
  const FrameRecord frame{
      project.clip, glm::inverse(project.clip), project.view, projection, double(width), double(height), p.sample_px};
  frame_ = scratch_of(std::vector<FrameRecord>{frame});
  counts_.reserve((size_t(tables.bound) + 1) * sizeof(uint32_t)), samples_.reserve(capacity_ * sizeof(SampleRecord));
  total_.reserve(sizeof(uint32_t)), fit_runs_.reserve(sizeof(FitRunRecord));
  clear_buffer(total_);
  if (tables.bound == 0) return;
  for (const Program* s : {&count_, &write_}) {
    glProgramUniform1ui(s->id(), s->uniform("listed_at"), tables.listed.at);
    glProgramUniform1ui(s->id(), s->uniform("capacity"), capacity_);
    glProgramUniform1ui(s->id(), s->uniform("with_knots"), fit_runs ? 1u : 0u);
    glProgramUniform1ui(s->id(), s->uniform("seed"), seed);
  }
  over_listed_(*tables.listed.buffer, tables.listed.at);
  auto over_runs = [&](const Program& s) {
    const Buffer* bound_at[] = {tables.paths,    tables.points,
                                tables.runs,     tables.listed.buffer,
                                &counts_.buffer, fit_runs ? fit_runs : &fit_runs_.buffer,
                                &knots,          &samples_.buffer,
                                &frame_.buffer,  &total_.buffer};
    for (GLuint b = 0; b < 10; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound_at[b]->id());
    over_listed_.dispatch(s);
  };
  over_runs(count_);
  scan_(counts_, size_t(tables.bound) + 1, *tables.listed.buffer, tables.listed.at, 1);
  over_runs(write_);
}

std::vector<BrushSample> BrushSamples::samples() const {
  uint32_t total = 0;
  if (total_.bytes > 0) read_buffer(total_, &total, sizeof total);
  std::vector<SampleRecord> records(total);
  if (!records.empty()) read_buffer(samples_, records.data(), records.size() * sizeof(SampleRecord));
  std::vector<BrushSample> out;
  for (const SampleRecord& r : records) out.push_back({{r.x, r.y, r.z}, r.t, r.stroke, r.path});
  return out;
}

}  // namespace plumbago::gpu
