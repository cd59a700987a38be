// The votes of coherent silhouettes on the GPU: see gpu/strokes/brush_votes.hpp.
#include "gpu/strokes/brush_votes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/strokes/strokes.hpp"
#include "common/util/memory_budget.hpp"
#include "gpu/strokes/brush_samples.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_votes.comp (std430).
struct SampleRecord {
  double x, y, z, t;
  uint32_t stroke, path;
};
struct VoteRecord {
  double s, t;
  uint32_t run, stroke, path, pad;
};
struct FrameRecord {
  glm::dmat4 clip, view;
  double width, height, search_px, depth_tolerance, cell;
  uint32_t columns, rows;
  double pad[2] = {0, 0};  // std430 rounds the struct to 32 bytes (its dmat4)
};
static_assert(sizeof(SampleRecord) == 40 && sizeof(VoteRecord) == 32 && sizeof(FrameRecord) == 320,
              "std430 layouts of brush_votes.comp");
constexpr size_t kPieceBytes = 80;  // brush_votes.comp Piece (std430: 16-aligned for its dvec2)
constexpr uint32_t kNoVote = 0xffffffffu;

Program step(const char* name) {
  return Program::compute("strokes/brush_votes.comp", std::string("#define ") + name + "\n");
}

}  // namespace

BrushVotes::BrushVotes() : pieces_(step("STEP_PIECES")), bin_(step("STEP_BIN")), vote_(step("STEP_VOTE")) {}

void BrushVotes::operator()(const std::vector<BrushSample>& previous, const Camera& camera, int width, int height,
                            const RunTables& tables, const CoherenceParams& p) {
  std::vector<SampleRecord> samples;
  for (const BrushSample& b : previous) samples.push_back({b.world.x, b.world.y, b.world.z, b.t, b.stroke, b.path});
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
  slots_ = tables.bound == 0 ? 0 : slots;  // no runs listed: no votes
  if (slots_ == 0) return;
  double bound = 1;  // the silhouette runs' pieces: their points less one each
  for (const RunBound& b : tables.bounds)
    if (b.style == PathTable::kSilhouetteStyle) bound += b.points;
  check_memory_budget("the brush votes of " + std::to_string(slots) + " samples over " + std::to_string(tables.bound) +
                          " runs on the GPU",
                      double(slots) * double(sizeof(VoteRecord)) + bound * double(kPieceBytes + 5 * sizeof(uint32_t)));
  // The reference's grid (common/strokes/coherent_silhouettes.cpp brush_votes).
  const double cell = std::max(4.0, 2 * p.search_px);
  const auto columns = uint32_t(std::ceil(width / cell)) + 1, rows = uint32_t(std::ceil(height / cell)) + 1;
  const auto pieces = size_t(std::ceil(bound)), cells = size_t(columns) * rows;
  votes_.reserve(slots * sizeof(VoteRecord)), pieces_at_.reserve(pieces * kPieceBytes);
  cells_.reserve((cells + 1) * sizeof(uint32_t)), entries_.reserve(4 * pieces * sizeof(uint32_t));
  longs_.reserve(pieces * sizeof(uint32_t)), counts_.reserve(2 * sizeof(uint32_t));
  WindowProjection project(camera, width, height);
  const FrameRecord frame{project.clip, project.view, double(width), double(height), p.search_px, p.depth_tolerance,
                          cell,         columns,      rows};
  frame_ = scratch_of(std::vector<FrameRecord>{frame});
  glProgramUniform1ui(vote_.id(), vote_.uniform("slots"), GLuint(slots));
  glProgramUniform1ui(pieces_.id(), pieces_.uniform("listed_at"), tables.listed.at);
  for (const Program* s : {&pieces_, &bin_, &vote_})
    glProgramUniform1ui(s->id(), s->uniform("piece_capacity"), GLuint(pieces));
  clear_buffer(cells_), clear_buffer(counts_), clear_buffer(votes_, kNoVote);  // a slot past the samples: no vote
  const Buffer* bound_at[] = {tables.paths,   tables.points,    tables.runs,   tables.listed.buffer, &samples,
                              &votes_.buffer, &frame_.buffer,   &total,        &pieces_at_.buffer,   &counts_.buffer,
                              &cells_.buffer, &entries_.buffer, &longs_.buffer};
  const auto bind = [&] {
    for (GLuint b = 0; b < 13; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound_at[b]->id());
  };
  over_(*tables.listed.buffer, tables.listed.at);
  bind();
  over_.dispatch(pieces_);
  scan_(cells_, cells);
  over_(counts_, 0);
  bind();  // the scan and the groups bind their own
  over_.dispatch(bin_);
  over_(total, 0);
  bind();
  over_.dispatch(vote_);
}

std::vector<BrushVote> BrushVotes::votes() const {
  std::vector<VoteRecord> records(slots_);
  if (records.empty()) return {};
  read_buffer(votes_, records.data(), records.size() * sizeof(VoteRecord));
  std::vector<BrushVote> out;
  for (const VoteRecord& v : records)
    if (v.run != kNoVote) out.push_back({v.run, v.s, v.t, v.stroke, v.path});
  return out;
}

}  // namespace plumbago::gpu
