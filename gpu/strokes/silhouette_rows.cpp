// The silhouette paths as window paths on the GPU: see gpu/strokes/silhouette_rows.hpp.
#include "gpu/strokes/silhouette_rows.hpp"

#include <algorithm>
#include <string>

#include "common/util/memory_budget.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

// shaders/strokes/silhouette_rows.comp's Counts (std430).
struct Counts {
  glm::uvec4 args;   // the groups over the paths, and their count
  uint32_t sums[8];  // 64-bit (low, high): first-round samples, runs, run length, points
  uint32_t kept, entries, pad[2];
  double sum(int i) const { return double(sums[2 * i]) + 4294967296.0 * double(sums[2 * i + 1]); }
};
static_assert(sizeof(Counts) == 64);

Program step(const char* name) {
  return Program::compute("strokes/silhouette_rows.comp", table_prelude() + "#define " + name + "\n");
}

}  // namespace

SilhouetteRows::SilhouetteRows(size_t records)
    : args_(step("STEP_ARGS")),
      pieces_step_(step("STEP_PIECES")),
      rows_step_(step("STEP_ROWS")),
      totals_(step("STEP_TOTALS")),
      records_(records) {
  check_memory_budget(
      "the silhouette rows of " + std::to_string(records) + " faces on the GPU",
      double(records) * double(sizeof(glm::uvec4) + 2 * sizeof(uint32_t) + sizeof(PathRow) + 2 * sizeof(PointRow)));
  const size_t n = records + 1;  // a prefix sum's total after the paths
  counts_ = make_buffer(nullptr, sizeof(Counts));
  pieces_ = make_buffer(nullptr, n * sizeof(glm::uvec4));
  kept_ = make_buffer(nullptr, n * sizeof(uint32_t));
  entries_ = make_buffer(nullptr, n * sizeof(uint32_t));
}

void SilhouetteRows::bind(const Texture& paths, const SilhouettePoints& points, const UploadedPaths& table) const {
  const Buffer* bound[] = {&counts_, &points.points(), &points.worlds(),    &pieces_,
                           &kept_,   &entries_,        &table.paths.buffer, &table.points.buffer};
  for (GLuint b = 0; b < 8; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  for (const Program* p : {&args_, &pieces_step_, &rows_step_, &totals_}) bind_textures(*p, {{"path_table", &paths}});
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counts_.id());
}

void SilhouetteRows::operator()(const Texture& paths, const SilhouettePoints& points, const SilhouetteRowFrame& frame,
                                UploadedPaths& table) {
  const GLuint zero = 0;
  glClearNamedBufferData(counts_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  for (const Program* p : {&pieces_step_, &rows_step_}) {
    glProgramUniform1f(p->id(), p->uniform("near"), frame.near);
    glProgramUniform1f(p->id(), p->uniform("width"), float(frame.width));
    glProgramUniform1f(p->id(), p->uniform("height"), float(frame.height));
    glProgramUniform1f(p->id(), p->uniform("step_px"), frame.step_px);
    glProgramUniform1ui(p->id(), p->uniform("first_path"), table.gpu_first);
    glProgramUniform1ui(p->id(), p->uniform("first_point"), table.cpu_points);
    glProgramUniform1ui(p->id(), p->uniform("first_entry"), table.first_gpu_entry);
    glProgramUniform1ui(p->id(), p->uniform("silhouette_base"), frame.silhouette_base);
  }
  bind(paths, points, table);
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(pieces_step_.id());
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(kept_, records_ + 1, counts_, 3, 1);  // over the paths the GPU counted (args.w)
  scan_(entries_, records_ + 1, counts_, 3, 1);
  bind(paths, points, table);
  glUseProgram(rows_step_.id());
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(totals_.id());
  glDispatchCompute(1, 1, 1);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  Counts c{};
  read_buffer(counts_, &c, sizeof c);
  table.add_gpu_paths(c.kept, c.entries);
  table.gpu_first_round = c.sum(0);
  table.gpu = {2, c.sum(1), c.sum(2), c.sum(3)};  // PathTable::style_of a silhouette
}

}  // namespace plumbago::gpu
