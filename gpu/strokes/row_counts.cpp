// What the GPU's window-path steps count: see gpu/strokes/row_counts.hpp.
#include "gpu/strokes/row_counts.hpp"

#include <string>

namespace plumbago::gpu {

RowCounts RowCounts::read(const Buffer& buffer) {
  RowCounts c{};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  read_buffer(buffer, &c, sizeof c);
  return c;
}

void RowCounts::add_bounds_to(UploadedPaths& table) const {
  for (uint32_t style = 0; style < 3; ++style) {  // PathTable::style_of: crease, border, silhouette
    table.gpu_first_round += sum(int(style), 0);
    if (sum(int(style), 1) > 0)
      table.gpu.push_back({style, sum(int(style), 1), sum(int(style), 2), sum(int(style), 3)});
  }
}

namespace {

Program step(const char* name) {
  return Program::compute("strokes/table_rows.comp", std::string("#define ") + name + "\n");
}

}  // namespace

TableRows::TableRows() : place_(step("STEP_PLACE")), header_(step("STEP_HEADER")) {}

void TableRows::operator()(const Buffer& counts, const UploadedPaths& table) const {
  const Buffer* at[] = {&counts, &table.paths.buffer, &table.points.buffer, &table.cpu_rows.buffer};
  for (GLuint k = 0; k < 4; ++k) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, k, at[k]->id());
  for (const Program* p : {&place_, &header_}) {
    glProgramUniform1ui(p->id(), p->uniform("cpu_paths"), table.cpu_paths);
    glProgramUniform1ui(p->id(), p->uniform("cpu_entries"), table.cpu_entries);
    glProgramUniform1ui(p->id(), p->uniform("cpu_silhouette_entry"), table.cpu_silhouette_entry);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (table.cpu_paths > 0) {
    const glm::uvec3 groups = row_groups(table.cpu_paths);
    glUseProgram(place_.id());
    glDispatchCompute(groups.x, groups.y, groups.z);
  }
  glUseProgram(header_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace plumbago::gpu
