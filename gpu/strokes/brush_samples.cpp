// The brush samples of coherent silhouettes on the GPU: see gpu/strokes/brush_samples.hpp.
#include "gpu/strokes/brush_samples.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/strokes/strokes.hpp"
#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_samples.comp (std430).
struct SampleRecord {
  double x, y, z, t;
  uint32_t stroke, pad;
};
struct RunKnots {
  uint32_t first, count;
};
struct FrameRecord {
  glm::dmat4 clip, unclip, view, projection;
  double width, height, sample_px, pad = 0;
};
static_assert(sizeof(SampleRecord) == 40 && sizeof(RunKnots) == 8 && sizeof(FrameRecord) == 544,
              "std430 layouts of brush_samples.comp");

Program step(const char* name) {
  return Program::compute("strokes/brush_samples.comp", std::string("#define ") + name + "\n");
}

}  // namespace

BrushSamples::BrushSamples() : count_(step("STEP_COUNT")), write_(step("STEP_WRITE")) {}

void BrushSamples::operator()(const RunTables& tables, const Camera& camera, int width, int height,
                              const std::vector<BrushParameter>& parameters, const CoherenceParams& p) {
  runs_ = tables.bound, listed_ = tables.listed;
  double bound = 1;  // n + 1 samples a run, n <= L / sample_px + 1
  for (const RunBound& b : tables.bounds) bound += b.length / p.sample_px + 2 * b.runs;
  check_memory_budget("the brush samples of " + std::to_string(runs_) + " runs on the GPU",
                      bound * double(sizeof(SampleRecord)));
  capacity_ = uint32_t(std::ceil(bound));
  std::vector<RunKnots> run_knots;
  std::vector<glm::dvec2> knots;
  for (const BrushParameter& k : parameters) {
    run_knots.push_back({uint32_t(knots.size()), uint32_t(k.size())});
    knots.insert(knots.end(), k.begin(), k.end());
  }
  run_knots.resize(std::max<size_t>(runs_, 1), RunKnots{0, 0});
  run_knots_ = scratch_of(run_knots), knots_ = scratch_of(knots);
  WindowProjection project(camera, width, height);
  glm::dmat4 projection = glm::dmat4(camera.projection(float(width) / float(height)));
  const FrameRecord frame{
      project.clip, glm::inverse(project.clip), project.view, projection, double(width), double(height), p.sample_px};
  frame_ = scratch_of(std::vector<FrameRecord>{frame});
  counts_.reserve((size_t(runs_) + 1) * sizeof(uint32_t)), samples_.reserve(capacity_ * sizeof(SampleRecord));
  for (const Program* s : {&count_, &write_}) {
    glProgramUniform1ui(s->id(), s->uniform("listed_at"), tables.listed.at);
    glProgramUniform1ui(s->id(), s->uniform("capacity"), capacity_);
    glProgramUniform1ui(s->id(), s->uniform("with_knots"), parameters.empty() ? 0u : 1u);
  }
  auto over_runs = [&](const Program& s) {
    const Buffer* bound_at[] = {tables.paths,         tables.points,    tables.runs,
                                tables.listed.buffer, &counts_.buffer,  &run_knots_.buffer,
                                &knots_.buffer,       &samples_.buffer, &frame_.buffer};
    for (GLuint b = 0; b < 9; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound_at[b]->id());
    dispatch_strided(s, runs_);
  };
  if (runs_ == 0) return;
  over_runs(count_);
  scan_(counts_, size_t(runs_) + 1, *tables.listed.buffer, tables.listed.at, 1);
  over_runs(write_);
}

std::vector<BrushSample> BrushSamples::samples() const {
  if (runs_ == 0) return {};
  uint32_t total = 0;  // after the scan, at the slot past the runs listed
  read_buffer(counts_, &total, sizeof total, size_t(listed_.read()) * sizeof(uint32_t));
  std::vector<SampleRecord> records(std::min(total, capacity_));
  if (!records.empty()) read_buffer(samples_, records.data(), records.size() * sizeof(SampleRecord));
  std::vector<BrushSample> out;
  for (const SampleRecord& r : records) out.push_back({{r.x, r.y, r.z}, r.t, r.stroke});
  return out;
}

}  // namespace plumbago::gpu
