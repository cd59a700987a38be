// The ID image's lines on the GPU: see gpu/strokes/id_lines.hpp.
#include "gpu/strokes/id_lines.hpp"

namespace plumbago::gpu {

namespace {

Program step(const char* name) {
  return Program::compute("strokes/id_lines.comp", std::string("#define ") + name + "\n");
}

}  // namespace

void IdLines::bind(const UploadedPaths& table) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, table.paths.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, table.points.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, pieces_.id());
}

IdLines::IdLines()
    : count_(step("STEP_COUNT")),
      args_(step("STEP_ARGS")),
      draw_(Program::with_geometry("strokes/id_lines.vert", "strokes/id_lines.geom", "strokes/id_image.frag")),
      empty_(make_vertex_array()) {}

void IdLines::prepare(const UploadedPaths& table, const StrokesParams& p, int width, int height, float near) {
  commands_ = 0;
  if (table.path_bound == 0) return;
  commands_ = size_t(table.entry_bound) + 1;  // after the counts and their total
  const size_t slots = commands_ + 8;         // two draws' commands
  // Kept across frames, not cleared: the steps write every slot they read.
  if (slots > capacity_) pieces_ = make_buffer(nullptr, slots * sizeof(uint32_t)), capacity_ = slots;
  for (const Program* program : {&count_, &args_, &draw_}) {
    GLuint id = program->id();
    glProgramUniform1ui(id, program->uniform("commands_at"), GLuint(commands_));
    glProgramUniform1f(id, program->uniform("width"), float(width));
    glProgramUniform1f(id, program->uniform("height"), float(height));
    glProgramUniform1f(id, program->uniform("near"), near);
    glProgramUniform1f(id, program->uniform("crease_px"), p.id_crease_px);
    glProgramUniform1f(id, program->uniform("crease_bias"), p.id_crease_depth_bias);
    glProgramUniform1f(id, program->uniform("silhouette_px"), p.id_silhouette_px);
    glProgramUniform1f(id, program->uniform("silhouette_bias"), p.id_depth_bias);
    glProgramUniform1f(id, program->uniform("silhouette_lift"), p.id_silhouette_lift);
  }
  bind(table);
  glUseProgram(count_.id());
  table.dispatch_over_entries();
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_(pieces_, commands_, table.paths, offsetof(TableHeader, entries) / sizeof(uint32_t), 1);
  bind(table);
  glUseProgram(args_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform2f(draw_.id(), draw_.uniform("window_size"), float(width), float(height));
}

void IdLines::draw(const UploadedPaths& table, IdLineRule rule) {
  if (commands_ == 0) return;
  const size_t command = commands_ + (rule == IdLineRule::Silhouettes ? 4 : 0);
  bind(table);
  glUseProgram(draw_.id());
  glBindVertexArray(empty_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, pieces_.id());
  glDrawArraysIndirect(GL_POINTS, reinterpret_cast<const void*>(command * sizeof(uint32_t)));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace plumbago::gpu
