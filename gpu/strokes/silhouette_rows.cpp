// The silhouette paths as window paths on the GPU: see gpu/strokes/silhouette_rows.hpp.
#include "gpu/strokes/silhouette_rows.hpp"

#include <algorithm>
#include <string>

#include "common/util/memory_budget.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

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
  pieces_ = make_buffer(nullptr, n * sizeof(glm::uvec4));
  kept_ = make_buffer(nullptr, n * sizeof(uint32_t));
  entries_ = make_buffer(nullptr, n * sizeof(uint32_t));
}

void SilhouetteRows::bind(const Texture& paths, const SilhouettePoints& points, const Buffer& counts,
                          const UploadedPaths& table) const {
  const Buffer* bound[] = {&counts, &points.points(), &points.worlds(),    &pieces_,
                           &kept_,  &entries_,        &table.paths.buffer, &table.points.buffer};
  for (GLuint b = 0; b < 8; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
  for (const Program* p : {&args_, &pieces_step_, &rows_step_, &totals_}) bind_textures(*p, {{"path_table", &paths}});
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counts.id());
}

void SilhouetteRows::operator()(const Texture& paths, const SilhouettePoints& points, const RowFrame& frame,
                                uint32_t first_point, const Buffer& counts, const UploadedPaths& table) {
  for (const Program* p : {&pieces_step_, &rows_step_}) {
    glProgramUniform1f(p->id(), p->uniform("near"), frame.near);
    glProgramUniform1f(p->id(), p->uniform("width"), float(frame.width));
    glProgramUniform1f(p->id(), p->uniform("height"), float(frame.height));
    glProgramUniform1f(p->id(), p->uniform("step_px"), frame.step_px);
    glProgramUniform1ui(p->id(), p->uniform("first_point"), first_point);
  }
  bind(paths, points, counts, table);
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(pieces_step_.id());
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(kept_, records_ + 1, counts, 3, 1);  // over the paths the GPU counted (silhouette_args.w)
  scan_(entries_, records_ + 1, counts, 3, 1);
  bind(paths, points, counts, table);
  glUseProgram(rows_step_.id());
  glDispatchComputeIndirect(0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(totals_.id());
  glDispatchCompute(1, 1, 1);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace plumbago::gpu
