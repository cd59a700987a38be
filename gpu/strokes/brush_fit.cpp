// The fit of coherent silhouettes on the GPU: see gpu/strokes/brush_fit.hpp.
#include "gpu/strokes/brush_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_fit.comp (std430).
struct VoteRecord {
  double s, t;
  uint32_t stroke, group = 0;
};
struct RunRecord {
  double length;
  uint32_t first_vote, vote_count, first_knot, knot_count = 0;
};
struct GroupRecord {
  uint32_t stroke, first, last, size, order, pad;
};
struct ClaimRecord {
  double from, to, piece_from, piece_to;
  uint32_t group, pad;
};
struct RowRecord {
  double m0, m1, m2, b;
};
struct ParamsRecord {
  double sample_px, jump_px, knot_px, scale_weight, distort_weight;
  uint32_t claim_votes, run_count;
};
static_assert(sizeof(VoteRecord) == 24 && sizeof(RunRecord) == 24 && sizeof(GroupRecord) == 24 &&
                  sizeof(ClaimRecord) == 40 && sizeof(RowRecord) == 32 && sizeof(ParamsRecord) == 48,
              "std430 layouts of brush_fit.comp");

template <class T>
void upload(ScratchBuffer& to, const std::vector<T>& records) {
  to = {make_buffer(records.data(), records.size() * sizeof(T)), records.size() * sizeof(T)};
}

}  // namespace

double knot_bound(double length_px, size_t votes, const CoherenceParams& p) {
  return std::floor(length_px / p.knot_px) + 4.0 * double(votes) + 2;
}

BrushFit::BrushFit() : fit_(Program::compute("strokes/brush_fit.comp")) {}

void BrushFit::operator()(const std::vector<std::vector<BrushVote>>& votes, const std::vector<double>& lengths,
                          const CoherenceParams& p) {
  run_count_ = votes.size();
  std::vector<VoteRecord> vote_records;
  std::vector<RunRecord> runs;
  double knots = 0;
  for (size_t r = 0; r < votes.size(); ++r) {
    runs.push_back({lengths.at(r), uint32_t(vote_records.size()), uint32_t(votes[r].size()), uint32_t(knots)});
    for (const BrushVote& v : votes[r]) vote_records.push_back({v.s, v.t, v.stroke});
    knots += votes[r].empty() ? 0.0 : knot_bound(lengths[r], votes[r].size(), p);
  }
  size_t n = vote_records.size();
  check_memory_budget("the brush fit of " + std::to_string(n) + " votes on the GPU",
                      double(n) * double(sizeof(VoteRecord) + sizeof(GroupRecord) + 2 * sizeof(ClaimRecord)) +
                          knots * double(sizeof(RowRecord) + sizeof(glm::dvec2)));
  upload(votes_, vote_records);
  upload(runs_, runs);
  upload(params_, std::vector<ParamsRecord>{{p.sample_px, p.jump_px, p.knot_px, p.scale_weight, p.distort_weight,
                                             uint32_t(std::max(1, p.claim_votes)), uint32_t(run_count_)}});
  groups_.reserve(n * sizeof(GroupRecord)), claims_.reserve(2 * n * sizeof(ClaimRecord));
  rows_.reserve(size_t(knots) * sizeof(RowRecord)), knots_.reserve(size_t(knots) * sizeof(glm::dvec2));
  const ScratchBuffer* bound[] = {&votes_, &runs_, &groups_, &claims_, &rows_, &knots_, &params_};
  for (GLuint b = 0; b < 7; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  glUseProgram(fit_.id());
  glDispatchCompute(GLuint(std::clamp<size_t>((run_count_ + 63) / 64, 1, 65535)), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

std::vector<BrushParameter> BrushFit::parameters() const {
  std::vector<RunRecord> runs(run_count_);
  if (runs.empty()) return {};
  read_buffer(runs_, runs.data(), runs.size() * sizeof(RunRecord));
  std::vector<BrushParameter> out;
  for (const RunRecord& r : runs) {
    out.emplace_back(r.knot_count);
    if (r.knot_count > 0)
      read_buffer(knots_, out.back().data(), r.knot_count * sizeof(glm::dvec2), r.first_knot * sizeof(glm::dvec2));
  }
  return out;
}

}  // namespace plumbago::gpu
