// Silhouette chains on the GPU (Kalnins et al. 2002, §4.5), the twin of
// reference/strokes/silhouette_chains.cpp: the segments are linked and compacted, then ranked
// by pointer jumping (Wyllie 1979), twice; the second also sums the window arc lengths.
// Each round is an indirect dispatch whose size the GPU writes: over the compacted segments,
// or in a ranking round after the first, over those the round before moved a pointer of (the
// others are done). bit_width(records) rounds are issued (enough for a chain through every
// face), and those past 2^k >= the segments' count (more than any chain needs) dispatch no
// work, nor do the rounds of either phase after one that changed nothing
// (shaders/strokes/silhouette_chains.comp says why that is safe). The CPU never learns the
// count: nothing is read back.
#include "common/strokes/silhouette_chains.hpp"

#include <algorithm>
#include <bit>

#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

Program step(const char* name) {
  return Program::compute("strokes/silhouette_chains.comp", table_prelude() + "#define " + name + "\n");
}

class SilhouetteChainsPass : public GpuPass {
 public:
  explicit SilhouetteChainsPass(GpuFrame& f)
      : link_(step("STEP_LINK")),
        args_(step("STEP_ARGS")),
        loops_(step("STEP_LOOPS")),
        cut_(step("STEP_CUT")),
        rank_(step("STEP_RANK")),
        write_(step("STEP_WRITE")) {
    std::vector<glm::uvec4> links = slot_links(f.scene, f.get(kLineMeshes));
    records_ = uint32_t(links.size());
    rounds_ = int(std::bit_width(records_));
    const size_t n = std::max<size_t>(records_, 1);
    slot_links_ = make_buffer(links.data(), n * sizeof(glm::uvec4));
    links_ = make_buffer(nullptr, n * sizeof(glm::uvec4));
    members_ = make_buffer(nullptr, n * sizeof(uint32_t));
    count_ = make_buffer(nullptr, kRoundArgs + (2 * 32 * 4 + 3 * 32) * sizeof(uint32_t));
    jump_ = make_buffer(nullptr, 2 * n * sizeof(glm::uvec4));  // two halves of `records_` rows
    arc_ = make_buffer(nullptr, 2 * n * sizeof(glm::vec2));
    active_ = make_buffer(nullptr, 2 * n * sizeof(uint32_t));  // two halves of `records_`
  }

  void run(GpuFrame& f) override {
    // Every record's rows are written each frame (the link step zeroes those of no member).
    const Texture &chains = table_target(f, records_, kChains), &arcs = table_target(f, records_, kChainArcs);
    const GLuint none = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, count_.id());
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    bind(f, chains, arcs);
    dispatch_in_chunks(link_, records_, "first_record");
    barrier();
    dispatch_in_chunks(args_, 1, "first_record");
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    for (int r = 0; r < rounds_; ++r)
      over_members(loops_, round_args(r), r);  // each loop's lowest record, chains' ends
    over_members(cut_, kAllMembers);
    for (int r = 0; r < rounds_; ++r) over_members(rank_, rank_args(r), r);  // starts, ranks, ends
    over_members(write_, kAllMembers);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }

 private:
  void bind(GpuFrame& f, const Texture& chains, const Texture& arcs) {
    for (const Program* p : {&link_, &args_, &loops_, &cut_, &rank_, &write_}) {
      bind_textures(
          *p, {{"facing", &f.get(kSegmentFacing)}, {"slots", &f.get(kSegmentSlots)}, {"ends", &f.get(kSegmentEnds)}});
      glProgramUniform1ui(p->id(), p->uniform("records"), records_);
      glProgramUniform1ui(p->id(), p->uniform("rounds"), GLuint(rounds_));
    }
    glBindImageTexture(0, chains.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, arcs.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, slot_links_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, links_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, members_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, count_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, jump_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, arc_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, active_.id());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, count_.id());
  }

  // Where the Count buffer (shaders/strokes/silhouette_chains.comp) holds each dispatch's groups.
  static constexpr GLintptr kAllMembers = 4, kRoundArgs = 16;
  static GLintptr round_args(int r) { return kRoundArgs + GLintptr(r) * 16; }
  static GLintptr rank_args(int r) { return round_args(32 + r); }

  // A dispatch whose groups the GPU wrote at `args`: round `round` of a phase, or over every member.
  static void over_members(const Program& p, GLintptr args, int round = -1) {
    glUseProgram(p.id());
    if (round >= 0) glProgramUniform1ui(p.id(), p.uniform("round_index"), GLuint(round));
    glDispatchComputeIndirect(args);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  }

  static void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

  Program link_, args_, loops_, cut_, rank_, write_;
  uint32_t records_ = 0;
  int rounds_ = 0;
  Buffer slot_links_, links_, members_, count_, jump_, arc_, active_;
};

}  // namespace

PLUMBAGO_GPU_PASS(silhouette_chains, {{"silhouette_chains"}, {}, make_pass<SilhouetteChainsPass>, Probe::Compute});

}  // namespace plumbago::gpu
