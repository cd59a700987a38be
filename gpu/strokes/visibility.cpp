// Visibility of stroke samples on the GPU (Kalnins et al. 2002, §4.6, §4.1), the twin of
// common/strokes/visibility.cpp: from the frame's path table, which the ID image put up
// (gpu/strokes/window_paths.hpp; parity feeds make their own), compute shaders
// (shaders/strokes/visibility.comp) take the first round of samples segment by segment,
// test them against the ID image, bisect each change to 1 px in one invocation and list the
// runs, placing everything by prefix sums. The buffers hold a bound on the samples the CPU
// takes from the paths, kept across frames; the steps over samples, and the prefix sums
// over their marks, go over the samples the GPU took, so the count stays on the GPU. Read
// back at the end: the totals and the runs' ends (Kalnins et al. read the whole ID image
// back every frame).
#include "gpu/strokes/visibility.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "common/util/memory_budget.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

namespace {

Program step(const char* name) {
  return Program::compute("strokes/visibility.comp", std::string("#define ") + name + "\n");
}

}  // namespace

SampleTest::SampleTest() : program_(step("STEP_TEST")) {}

std::vector<uint8_t> SampleTest::operator()(const Texture& ids, const std::vector<VisibilitySample>& batch) {
  Buffer samples = make_buffer(batch.data(), batch.size() * sizeof(VisibilitySample));
  Buffer flags = make_buffer(nullptr, batch.size() * sizeof(uint32_t));
  glProgramUniform1ui(program_.id(), program_.uniform("sample_count"), GLuint(batch.size()));
  bind_textures(program_, {{"ids", &ids}});
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, samples.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, flags.id());
  dispatch_in_chunks(program_, batch.size(), "first");
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<uint32_t> read(batch.size());
  read_buffer(flags, read.data(), read.size() * sizeof(uint32_t));
  return std::vector<uint8_t>(read.begin(), read.end());
}

namespace {

// shaders/strokes/visibility.comp's Tested (std430).
struct TestedRow {
  double s, change;
  uint32_t flags, path;
};
static_assert(sizeof(TestedRow) == 24);

// At least the first round's samples of `lines` (first_round_bound).
double first_round_samples(const WindowLines& lines, double step) {
  double bound = 0;
  for (const WindowPath& p : lines.paths) bound += first_round_bound(p, step, lines.width, lines.height);
  return bound;
}

uint32_t read_uint(const Buffer& b, size_t at) {
  uint32_t v = 0;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  read_buffer(b, &v, sizeof v, at * sizeof(uint32_t));
  return v;
}

class VisibilityPass : public GpuPass {
 public:
  explicit VisibilityPass(GpuFrame&)
      : count_(step("STEP_COUNT")),
        ends_(step("STEP_ENDS")),
        samples_(step("STEP_SAMPLES")),
        changes_step_(step("STEP_CHANGES")),
        args_(step("STEP_ARGS")),
        marks_(step("STEP_MARKS")),
        list_runs_(step("STEP_RUNS")) {}

  void run(GpuFrame& f) override {
    const WindowLines& lines = f.get(kWindowLines);
    Visibility v;
    tables_ = {};
    if (!lines.paths.empty()) v = visibility(f, lines);
    f.put(kRunTables, tables_);
    if (f.dump) {
      auto [paths, ends] = run_tables(v.runs);
      dumped_ = {{kFlags.name, flags_image(v.flags)}, {kRunPaths.name, paths}, {kRunEnds.name, ends}};
    }
    f.put(kVisibleRuns, std::move(v));
  }

  void dump(GpuFrame&, const std::vector<std::string>&, std::map<std::string, Image>& out) override {
    for (auto& [name, image] : dumped_) out[name] = image;
  }

 private:
  Visibility visibility(GpuFrame& f, const WindowLines& lines) {
    const auto p = f.params<StrokesParams>();
    const UploadedPaths* table = f.get(maybe(kPathTable));  // the ID image's, or (parity) one of its own
    if (!table) table = &own_.emplace(lines);
    const double bound = first_round_samples(lines, p.vis_step_px);
    check_memory(lines, p.vis_step_px, bound);
    const auto capacity = uint32_t(bound);
    const size_t n = std::max<size_t>(capacity, 1), args = size_t(table->entries) + 1;
    Buffer entries = make_zeroed_buffer(args + 6);  // the counts, their total, then two dispatches' groups
    reserve(n);
    set_uniforms(f, lines, *table, capacity);
    const std::initializer_list<const Buffer*> all = {&table->paths,  &table->points, &entries,  &tested_,
                                                      &change_marks_, &run_marks_,    &changes_, &run_rows_};
    bind(all);
    bind_textures(samples_, {{"ids", &f.get(kIds)}});
    bind_textures(changes_step_, {{"ids", &f.get(kIds)}});
    dispatch_in_chunks(count_, table->entries, "first");
    barrier();
    dispatch_in_chunks(ends_, table->count, "first");
    barrier();
    scan_(entries, args);
    bind(all);
    dispatch_in_chunks(samples_, table->entries, "first");
    glUseProgram(args_.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries.id());
    over_samples(changes_step_, args);
    scan_(change_marks_, n + 1, entries, args - 1, 1);  // over the samples the GPU took
    bind(all);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries.id());
    over_samples(marks_, args);
    scan_(run_marks_, 2 * n + 1, entries, args - 1, 2);
    bind(all);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries.id());
    over_samples(list_runs_, args + 3);
    Visibility v = read_runs(f, lines, {entries, args - 1}, run_marks_, run_rows_, tested_, capacity);
    tables_ = {&table->paths, &table->points, &run_rows_, uint32_t(v.runs.size())};
    return v;
  }

  // A step over the samples (or their run slots), with the groups the GPU wrote at uint `at`.
  static void over_samples(const Program& p, size_t at) {
    glUseProgram(p.id());
    glDispatchComputeIndirect(GLintptr(at * sizeof(uint32_t)));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  struct Total {
    const Buffer& buffer;
    size_t at;
  };

  // One readback after the frame's visibility work: the totals, then the runs (and, for a
  // dump, the flags).
  Visibility read_runs(const GpuFrame& f, const WindowLines& lines, Total samples, const Buffer& run_marks,
                       const Buffer& runs, const Buffer& tested, uint32_t capacity) {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    Visibility v;
    v.samples = read_uint(samples.buffer, samples.at);
    if (v.samples > capacity)
      throw std::logic_error("visibility: " + std::to_string(v.samples) + " samples over the bound of " +
                             std::to_string(capacity));
    std::vector<RunRow> rows(read_uint(run_marks, 2 * size_t(v.samples)));  // the run slots' total
    read_buffer(runs, rows.data(), rows.size() * sizeof(RunRow));
    for (const RunRow& r : rows)
      v.runs.push_back(run_from_row(lines.paths[r.path], r.path, r.s0, r.s1, r.flags, false));
    if (f.dump) {
      std::vector<TestedRow> t(v.samples);
      read_buffer(tested, t.data(), t.size() * sizeof(TestedRow));
      for (const TestedRow& row : t) v.flags.push_back(row.flags & 1u);
    }
    return v;
  }

  void set_uniforms(GpuFrame& f, const WindowLines& lines, const UploadedPaths& table, uint32_t capacity) {
    for (const Program* p : {&count_, &ends_, &samples_, &args_, &changes_step_, &marks_, &list_runs_}) {
      glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity);
      glProgramUniform1ui(p->id(), p->uniform("path_count"), table.count);
      glProgramUniform1ui(p->id(), p->uniform("entry_count"), table.entries);
      glProgramUniform1f(p->id(), p->uniform("step_px"), f.params<StrokesParams>().vis_step_px);
      glProgramUniform1f(p->id(), p->uniform("width"), float(lines.width));
      glProgramUniform1f(p->id(), p->uniform("height"), float(lines.height));
    }
  }

  // What the samples may take (the bound: their record, a mark and a change, two run marks
  // and two runs), against the memory budget before any is made.
  static void check_memory(const WindowLines& lines, double step, double bound) {
    char what[200];
    std::snprintf(what, sizeof what,
                  "the visibility samples of %zu lines on the GPU (at most %.0f, every "
                  "strokes.vis_step_px %g)",
                  lines.paths.size(), bound, step);
    check_memory_budget(what, bound * double(sizeof(TestedRow) + 4 + sizeof(glm::dvec2) + 8 + 2 * sizeof(RunRow)));
    if (bound > double(std::numeric_limits<uint32_t>::max() / 2 - 1))
      throw std::length_error(std::string(what) + ": more than 2^31 samples");
  }

  // Buffers for n samples, kept across frames and made anew where short (at the bound that
  // check_memory took). Nothing is cleared: the steps write every slot below the samples the
  // GPU took, and a prefix sum reads only the values before each slot.
  void reserve(size_t n) {
    if (n <= held_) return;
    held_ = n;
    tested_ = make_buffer(nullptr, held_ * sizeof(TestedRow));
    changes_ = make_buffer(nullptr, held_ * sizeof(glm::dvec2));
    change_marks_ = make_buffer(nullptr, (held_ + 1) * sizeof(uint32_t));
    run_marks_ = make_buffer(nullptr, (2 * held_ + 1) * sizeof(uint32_t));
    run_rows_ = make_buffer(nullptr, 2 * held_ * sizeof(RunRow));
  }

  static void bind(std::initializer_list<const Buffer*> buffers) {
    GLuint binding = 0;
    for (const Buffer* b : buffers) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding++, b->id());
  }

  static void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

  Program count_, ends_, samples_, changes_step_, args_, marks_, list_runs_;
  std::optional<UploadedPaths> own_;  // where no ID image pass made the table (parity)
  size_t held_ = 0;                   // samples the buffers below hold
  Buffer tested_, changes_, change_marks_, run_marks_;
  Buffer run_rows_;  // what the stroke pass reads (kRunTables), kept until the next frame
  RunTables tables_;
  ExclusiveScan scan_;
  std::map<std::string, Image> dumped_;
};

}  // namespace

PLUMBAGO_GPU_PASS(visibility, {{"visibility"}, {}, make_pass<VisibilityPass>, Probe::Compute});

}  // namespace plumbago::gpu
