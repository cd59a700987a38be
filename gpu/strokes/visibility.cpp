// Visibility of stroke samples on the GPU (Kalnins et al. 2002, §4.6, §4.1), the twin of
// common/strokes/visibility.cpp: from the frame's path table, which the ID image put up
// (gpu/strokes/window_paths.hpp; parity feeds make their own), compute shaders
// (shaders/strokes/visibility.comp) take the first round of samples segment by segment,
// test them against the ID image, bisect each change to 1 px in one invocation and list the
// runs, placing everything by prefix sums. The steps over entries and paths go by the
// table's header; the buffers hold a bound on the samples the CPU takes from the paths (in a
// frame that sizes them, UploadedPaths::sized; the frames after keep them), kept across
// frames; the steps over samples, and the prefix sums over their marks, go over the samples
// the GPU took (those past the buffers left out), so the count stays on the GPU, and so do
// the runs, for the stroke pass (gpu/strokes/window_paths.hpp): a frame reads nothing back
// (Kalnins et al. read the whole ID image back every frame); a dump reads the runs and flags.
#include "gpu/strokes/visibility.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
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

std::vector<uint8_t> SampleTest::operator()(const Texture& ids, const Texture* crease_ids,
                                            const std::vector<VisibilitySample>& batch) {
  Buffer samples = make_buffer(batch.data(), batch.size() * sizeof(VisibilitySample));
  Buffer flags = make_buffer(nullptr, batch.size() * sizeof(uint32_t));
  glProgramUniform1ui(program_.id(), program_.uniform("sample_count"), GLuint(batch.size()));
  bind_textures(program_, {{"ids", &ids}, {"crease_ids", crease_ids ? crease_ids : &ids}});
  glProgramUniform1i(program_.id(), program_.uniform("crease_under_silhouettes"), crease_ids != nullptr);
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

// At least the first round's samples of each path of `lines` that `table` has from the CPU
// (first_round_bound): none where the GPU wrote its rows.
std::vector<double> first_round_samples(const WindowLines& lines, const UploadedPaths& table, double step) {
  std::vector<double> bounds;
  if (!table.gpu_rows)
    for (const WindowPath& p : lines.paths) bounds.push_back(first_round_bound(p, step, lines.width, lines.height));
  return bounds;
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

  // The runs stay on the GPU (kRunTables) for the stroke pass; only a dump reads them back.
  void run(GpuFrame& f) override {
    const WindowLines& lines = f.get(kWindowLines);
    tables_ = {};
    const UploadedPaths* table = f.get(maybe(kPathTable));  // the ID image's, or (parity) one of its own
    if (!table) table = &own_.emplace(lines);
    if (table->path_bound > 0) list_runs(f, lines, *table);
    f.put(kRunTables, tables_);
    if (!f.dump) return;
    Visibility v = read_runs(tables_, lines);
    std::vector<TestedRow> tested(tables_.runs ? v.samples : 0);
    if (!tested.empty()) read_buffer(tested_, tested.data(), tested.size() * sizeof(TestedRow));
    for (const TestedRow& row : tested) v.flags.push_back(row.flags & 1u);
    auto [paths, ends] = run_tables(v.runs);
    dumped_ = {{kFlags.name, flags_image(v.flags)}, {kRunPaths.name, paths}, {kRunEnds.name, ends}};
    f.put(kVisibleRuns, std::move(v));
  }

  void dump(GpuFrame&, const std::vector<std::string>&, std::map<std::string, Image>& out) override {
    for (auto& [name, image] : dumped_) out[name] = image;
  }

 private:
  // `lines`: the window lines, which hold the paths of `table` the CPU made (and the GPU's
  // where they stay whole: GpuFrame::whole_lines).
  void list_runs(GpuFrame& f, const WindowLines& lines, const UploadedPaths& table) {
    const auto p = f.params<StrokesParams>();
    std::vector<double> path_samples;
    if (table.sized) {  // else the buffers an earlier frame sized, kept
      path_samples = first_round_samples(lines, table, p.vis_step_px);
      const double bound = std::accumulate(path_samples.begin(), path_samples.end(), table.gpu_first_round);
      check_memory(table.path_bound, p.vis_step_px, bound);
      capacity_ = uint32_t(bound);
    }
    const uint32_t capacity = capacity_;
    const size_t n = std::max<size_t>(capacity, 1), slots = size_t(table.entry_bound) + 1;
    // The counts and their total, then two dispatches' groups, the runs listed, the samples;
    // kept across frames, not cleared: the steps write every slot they read.
    entries_.reserve((slots + 8) * sizeof(uint32_t));
    reserve(n);
    set_uniforms(f, lines, capacity, slots);
    const std::initializer_list<const Buffer*> all = {&table.paths.buffer, &table.points.buffer,  &entries_.buffer,
                                                      &tested_.buffer,     &change_marks_.buffer, &run_marks_.buffer,
                                                      &changes_.buffer,    &run_rows_.buffer};
    bind(all);
    for (const Program* p : {&samples_, &changes_step_})
      bind_textures(*p, {{"ids", &f.get(kIds)}, {"crease_ids", &f.get(kCreaseIds)}});
    glUseProgram(count_.id());
    table.dispatch_over_entries();
    barrier();
    glUseProgram(ends_.id());
    table.dispatch_over_paths();
    barrier();
    scan_(entries_, slots, table.paths, offsetof(TableHeader, entries) / sizeof(uint32_t), 1);
    bind(all);
    glUseProgram(samples_.id());
    table.dispatch_over_entries();
    glUseProgram(args_.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries_.id());
    over_samples(changes_step_, slots);
    scan_(change_marks_, n + 1, entries_, slots + 7, 1);  // over the samples the GPU took
    bind(all);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries_.id());
    over_samples(marks_, slots);
    scan_(run_marks_, 2 * n + 1, entries_, slots + 7, 2);
    bind(all);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, entries_.id());
    over_samples(list_runs_, slots + 3);
    tables_.paths = &table.paths.buffer, tables_.points = &table.points.buffer, tables_.runs = &run_rows_.buffer;
    tables_.listed = {&entries_.buffer, uint32_t(slots + 6)}, tables_.samples = {&entries_.buffer, uint32_t(slots + 7)};
    tables_.bound = uint32_t(2 * n), tables_.sized = table.sized;
    for (size_t i = 0; i < path_samples.size(); ++i)
      tables_.bounds.push_back(run_bound(lines.paths[i], path_samples[i], lines.width, lines.height));
    tables_.bounds.insert(tables_.bounds.end(), table.gpu.begin(), table.gpu.end());
  }

  // A step over the samples (or their run slots), with the groups the GPU wrote at uint `at`.
  static void over_samples(const Program& p, size_t at) {
    glUseProgram(p.id());
    glDispatchComputeIndirect(GLintptr(at * sizeof(uint32_t)));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  void set_uniforms(GpuFrame& f, const WindowLines& lines, uint32_t capacity, size_t slots) {
    for (const Program* p : {&count_, &ends_, &samples_, &args_, &changes_step_, &marks_, &list_runs_}) {
      glProgramUniform1ui(p->id(), p->uniform("capacity"), capacity);
      glProgramUniform1ui(p->id(), p->uniform("slots_at"), GLuint(slots));
      glProgramUniform1f(p->id(), p->uniform("step_px"), f.params<StrokesParams>().vis_step_px);
      glProgramUniform1i(p->id(), p->uniform("crease_under_silhouettes"),
                         f.params<StrokesParams>().crease_under_silhouettes);
      glProgramUniform1f(p->id(), p->uniform("width"), float(lines.width));
      glProgramUniform1f(p->id(), p->uniform("height"), float(lines.height));
    }
  }

  // What the samples may take (the bound: their record, a mark and a change, two run marks
  // and two runs), against the memory budget before any is made.
  static void check_memory(uint32_t paths, double step, double bound) {
    char what[200];
    std::snprintf(what, sizeof what,
                  "the visibility samples of %u lines on the GPU (at most %.0f, every "
                  "strokes.vis_step_px %g)",
                  paths, bound, step);
    check_memory_budget(what, bound * double(sizeof(TestedRow) + 4 + sizeof(glm::dvec2) + 8 + 2 * sizeof(RunRow)));
    if (bound > double(std::numeric_limits<uint32_t>::max() / 2 - 1))
      throw std::length_error(std::string(what) + ": more than 2^31 samples");
  }

  // Buffers for n samples, kept across frames and made anew where short (at the bound that
  // check_memory took). Nothing is cleared: the steps write every slot below the samples the
  // GPU took, and a prefix sum reads only the values before each slot.
  void reserve(size_t n) {
    tested_.reserve(n * sizeof(TestedRow)), changes_.reserve(n * sizeof(glm::dvec2));
    change_marks_.reserve((n + 1) * sizeof(uint32_t)), run_marks_.reserve((2 * n + 1) * sizeof(uint32_t));
    run_rows_.reserve(2 * n * sizeof(RunRow));
  }

  static void bind(std::initializer_list<const Buffer*> buffers) {
    GLuint binding = 0;
    for (const Buffer* b : buffers) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding++, b->id());
  }

  static void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

  Program count_, ends_, samples_, changes_step_, args_, marks_, list_runs_;
  std::optional<UploadedPaths> own_;  // where no ID image pass made the table (parity)
  ScratchBuffer tested_, changes_, change_marks_, run_marks_;
  // What the stroke pass reads (kRunTables) and a dump reads back, kept until the next frame.
  ScratchBuffer run_rows_;
  ScratchBuffer entries_;
  uint32_t capacity_ = 0;  // the samples the buffers hold: the bound of the last frame that sized them
  RunTables tables_;
  ExclusiveScan scan_;
  std::map<std::string, Image> dumped_;
};

}  // namespace

PLUMBAGO_GPU_PASS(visibility, {{"visibility"}, {}, make_pass<VisibilityPass>, Probe::Compute});

}  // namespace plumbago::gpu
