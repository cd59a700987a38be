// The votes of coherent silhouettes on the GPU: see gpu/strokes/brush_votes.hpp.
#include "gpu/strokes/brush_votes.hpp"

#include <algorithm>
#include <string>

#include "common/strokes/strokes.hpp"
#include "common/util/memory_budget.hpp"
#include "gpu/strokes/brush_samples.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_votes.comp (std430).
struct SampleRecord {
  double x, y, z, t;
  uint32_t stroke, pad = 0;
};
struct VoteRecord {
  double s, t;
  uint32_t run, stroke;
};
struct FrameRecord {
  glm::dmat4 clip, view;
  double width, height, search_px, depth_tolerance;
};
static_assert(sizeof(SampleRecord) == 40 && sizeof(VoteRecord) == 24 && sizeof(FrameRecord) == 288,
              "std430 layouts of brush_votes.comp");
constexpr uint32_t kNoVote = 0xffffffffu;

Program step(const char* name) {
  return Program::compute("strokes/brush_votes.comp", std::string("#define ") + name + "\n");
}

}  // namespace

BrushVotes::BrushVotes() : box_(step("STEP_BOXES")), vote_(step("STEP_VOTE")) {}

void BrushVotes::operator()(const std::vector<BrushSample>& previous, const Camera& camera, int width, int height,
                            const RunTables& tables, const CoherenceParams& p) {
  std::vector<SampleRecord> samples;
  for (const BrushSample& b : previous) samples.push_back({b.world.x, b.world.y, b.world.z, b.t, b.stroke});
  samples_ = scratch_of(samples);
  total_ = scratch_of(std::vector<uint32_t>{uint32_t(samples.size())});
  vote(samples_, total_, samples.size(), camera, width, height, tables, p);
}

void BrushVotes::operator()(const BrushSamples& previous, const Camera& camera, int width, int height,
                            const RunTables& tables, const CoherenceParams& p) {
  vote(previous.buffer(), previous.total(), previous.capacity(), camera, width, height, tables, p);
}

void BrushVotes::vote(const Buffer& samples, const Buffer& total, size_t slots, const Camera& camera, int width,
                      int height, const RunTables& tables, const CoherenceParams& p) {
  slots_ = slots;
  if (slots == 0) return;
  check_memory_budget("the brush votes of " + std::to_string(slots) + " samples on the GPU",
                      double(slots) * double(sizeof(VoteRecord)));
  votes_.reserve(slots * sizeof(VoteRecord)), boxes_.reserve(std::max<size_t>(tables.bound, 1) * sizeof(glm::dvec4));
  WindowProjection project(camera, width, height);
  const FrameRecord frame{project.clip, project.view, double(width), double(height), p.search_px, p.depth_tolerance};
  frame_ = scratch_of(std::vector<FrameRecord>{frame});
  glProgramUniform1ui(vote_.id(), vote_.uniform("slots"), GLuint(slots));
  for (const Program* s : {&box_, &vote_}) glProgramUniform1ui(s->id(), s->uniform("listed_at"), tables.listed.at);
  const Buffer* bound[] = {tables.paths,   tables.points,  tables.runs, tables.listed.buffer, &samples,
                           &votes_.buffer, &frame_.buffer, &total,      &boxes_.buffer};
  for (GLuint b = 0; b < 9; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  dispatch_strided(box_, tables.bound);
  dispatch_strided(vote_, slots);
}

std::vector<BrushVote> BrushVotes::votes() const {
  std::vector<VoteRecord> records(slots_);
  if (records.empty()) return {};
  read_buffer(votes_, records.data(), records.size() * sizeof(VoteRecord));
  std::vector<BrushVote> out;
  for (const VoteRecord& v : records)
    if (v.run != kNoVote) out.push_back({v.run, v.s, v.t, v.stroke});
  return out;
}

}  // namespace plumbago::gpu
