// The fit of coherent silhouettes on the GPU: see gpu/strokes/brush_fit.hpp.
#include "gpu/strokes/brush_fit.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "common/util/memory_budget.hpp"

namespace plumbago::gpu {

namespace {

// The records of shaders/strokes/brush_fit.comp (std430).
struct VoteRecord {
  double s, t;
  uint32_t stroke, group = 0, path = 0, pad = 0;
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
static_assert(sizeof(VoteRecord) == 32 && sizeof(FitRunRecord) == 32 && sizeof(GroupRecord) == 24 &&
                  sizeof(ClaimRecord) == 40 && sizeof(RowRecord) == 32 && sizeof(ParamsRecord) == 48,
              "std430 layouts of brush_fit.comp");

}  // namespace

double knot_bound(double length_px, size_t votes, const CoherenceParams& p) {
  return std::floor(length_px / p.knot_px) + 4.0 * double(votes) + 2;
}

namespace {

Program bucket_step(const char* name) {
  return Program::compute("strokes/brush_buckets.comp", std::string("#define ") + name + "\n");
}

ParamsRecord params_record(const CoherenceParams& p, size_t runs) {
  return {p.sample_px,   p.jump_px, p.knot_px, p.scale_weight, p.distort_weight, uint32_t(std::max(1, p.claim_votes)),
          uint32_t(runs)};
}

}  // namespace

BrushFit::BrushFit()
    : fit_(Program::compute("strokes/brush_fit.comp")),
      count_(bucket_step("STEP_COUNT")),
      scatter_(bucket_step("STEP_SCATTER")),
      bounds_(bucket_step("STEP_BOUNDS")),
      runs_step_(bucket_step("STEP_RUNS")) {}

void BrushFit::operator()(const std::vector<std::vector<BrushVote>>& votes, const std::vector<double>& lengths,
                          const CoherenceParams& p) {
  run_count_ = votes.size(), listed_ = {};
  std::vector<VoteRecord> vote_records;
  std::vector<FitRunRecord> runs;
  double knots = 0;
  for (size_t r = 0; r < votes.size(); ++r) {
    runs.push_back({lengths.at(r), uint32_t(vote_records.size()), uint32_t(votes[r].size()), uint32_t(knots)});
    for (const BrushVote& v : votes[r]) vote_records.push_back({v.s, v.t, v.stroke, 0, v.path});
    knots += votes[r].empty() ? 0.0 : knot_bound(lengths[r], votes[r].size(), p);
  }
  reserve(vote_records.size(), knots);
  votes_ = scratch_of(vote_records), runs_ = scratch_of(runs);
  params_ = scratch_of(std::vector<ParamsRecord>{params_record(p, run_count_)});
  fit();
}

void BrushFit::operator()(const BrushVotes& votes, const RunTables& tables, const CoherenceParams& p) {
  run_count_ = tables.bound, listed_ = tables.listed;
  if (run_count_ == 0) return;
  double length = 0;  // of the runs, together
  for (const RunBound& b : tables.bounds) length += b.length + 2 * b.runs * p.knot_px;
  reserve(votes.slots(), std::floor(length / p.knot_px) + 4.0 * double(votes.slots()) + 1);
  votes_.reserve(std::max<size_t>(votes.slots(), 1) * sizeof(VoteRecord));
  runs_.reserve(run_count_ * sizeof(FitRunRecord));
  params_ = scratch_of(std::vector<ParamsRecord>{params_record(p, 0)});
  counts_.reserve((run_count_ + 1) * sizeof(uint32_t)), fill_.reserve((run_count_ + 1) * sizeof(uint32_t));
  clear_buffer(counts_), clear_buffer(fill_);
  for (const Program* s : {&count_, &scatter_, &bounds_, &runs_step_}) {
    glProgramUniform1ui(s->id(), s->uniform("vote_slots"), GLuint(votes.slots()));
    glProgramUniform1ui(s->id(), s->uniform("listed_at"), tables.listed.at);
  }
  over_listed_(*tables.listed.buffer, tables.listed.at);
  over_each_run_(*tables.listed.buffer, tables.listed.at);
  auto step = [&](const Program& s, std::optional<size_t> over) {
    const Buffer* bound[] = {&votes.buffer(), &counts_.buffer, &fill_.buffer,        &votes_.buffer,
                             &runs_.buffer,   tables.runs,     tables.listed.buffer, &params_.buffer};
    for (GLuint b = 0; b < 8; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
    over ? dispatch_strided(s, *over) : over_listed_.dispatch(s);
  };
  step(count_, votes.slots());
  scan_(counts_, run_count_ + 1, *tables.listed.buffer, tables.listed.at, 1);
  step(scatter_, votes.slots());
  step(bounds_, {});
  scan_(fill_, run_count_ + 1, *tables.listed.buffer, tables.listed.at, 1);
  step(runs_step_, {});
  fit();
}

void BrushFit::reserve(size_t votes, double knots) {
  check_memory_budget("the brush fit of " + std::to_string(votes) + " votes on the GPU",
                      double(votes) * double(sizeof(VoteRecord) + sizeof(GroupRecord) + 2 * sizeof(ClaimRecord)) +
                          knots * double(sizeof(RowRecord) + sizeof(glm::dvec2)));
  groups_.reserve(std::max<size_t>(votes, 1) * sizeof(GroupRecord));
  claims_.reserve(std::max<size_t>(2 * votes, 1) * sizeof(ClaimRecord));
  rows_.reserve(std::max<size_t>(size_t(knots), 1) * sizeof(RowRecord));
  knots_.reserve(std::max<size_t>(size_t(knots), 1) * sizeof(glm::dvec2));
}

// 3.-4. over the runs' records, as many as the parameters' run_count (at most run_count_).
void BrushFit::fit() {
  const ScratchBuffer* bound[] = {&votes_, &runs_, &groups_, &claims_, &rows_, &knots_, &params_};
  for (GLuint b = 0; b < 7; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  // One run a workgroup (brush_fit.comp).
  listed_.buffer ? over_each_run_.dispatch(fit_) : dispatch_strided(fit_, run_count_, 1);
}

std::vector<RunBrush> BrushFit::parameters() const {
  std::vector<FitRunRecord> runs(listed_.buffer ? listed_.read() : run_count_);
  if (runs.empty()) return {};
  read_buffer(runs_, runs.data(), runs.size() * sizeof(FitRunRecord));
  std::vector<RunBrush> out;
  for (const FitRunRecord& r : runs) {
    out.push_back({BrushParameter(r.knot_count), r.path});
    if (r.knot_count > 0)
      read_buffer(knots_, out.back().knots.data(), r.knot_count * sizeof(glm::dvec2),
                  r.first_knot * sizeof(glm::dvec2));
  }
  return out;
}

}  // namespace plumbago::gpu
