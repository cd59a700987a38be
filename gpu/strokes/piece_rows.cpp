// The steps after a window-path maker's points: see gpu/strokes/piece_rows.hpp.
#include "gpu/strokes/piece_rows.hpp"

namespace plumbago::gpu {

namespace {

Program step(const std::string& shader, const char* name) {
  return Program::compute(shader, std::string("#define ") + name + "\n");
}

}  // namespace

PieceRows::PieceRows(const std::string& shader)
    : pieces_step_(step(shader, "STEP_PIECES")),
      rows_step_(step(shader, "STEP_ROWS")),
      totals_(step(shader, "STEP_TOTALS")) {}

void PieceRows::set(const char* name, uint32_t value) const {
  for (const Program* p : {&pieces_step_, &rows_step_, &totals_}) glProgramUniform1ui(p->id(), p->uniform(name), value);
}

void PieceRows::operator()(const RowFrame& frame, size_t sources, uint32_t first_point, const Buffer& counts,
                           const UploadedPaths& table, const Buffer* const (&own)[2]) {
  pieces_.reserve((sources + 1) * sizeof(uint32_t));
  entries_.reserve((sources + 1) * sizeof(uint32_t));
  for (const Program* p : {&pieces_step_, &rows_step_, &totals_}) {
    glProgramUniform1f(p->id(), p->uniform("near"), frame.near);
    glProgramUniform1f(p->id(), p->uniform("width"), float(frame.width));
    glProgramUniform1f(p->id(), p->uniform("height"), float(frame.height));
    glProgramUniform1f(p->id(), p->uniform("step_px"), frame.step_px);
    glProgramUniform1ui(p->id(), p->uniform("source_count"), GLuint(sources));
    glProgramUniform1ui(p->id(), p->uniform("first_point"), first_point);
  }
  auto bind = [&] {
    const Buffer* bound[] = {&counts, own[0], own[1], &pieces_.buffer, &entries_.buffer};
    for (GLuint b = 0; b < 5; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, bound[b]->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, table.paths.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, table.points.id());
  };
  bind();
  over_rows(pieces_step_, sources);
  scan_(pieces_, sources + 1);
  scan_(entries_, sources + 1);
  bind();
  over_rows(rows_step_, sources);
  glUseProgram(totals_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void over_rows(const Program& step, size_t count) {
  const glm::uvec3 groups = row_groups(uint32_t(count));
  glUseProgram(step.id());
  if (groups.x > 0) glDispatchCompute(groups.x, groups.y, groups.z);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace plumbago::gpu
