// Dispatches over a count the GPU holds: see gpu/gl/groups.hpp.
#include "gpu/gl/groups.hpp"

namespace plumbago::gpu {

GroupsOver::GroupsOver(uint32_t group_size)
    : step_(Program::compute("util/groups.comp")), groups_(make_buffer(nullptr, 3 * sizeof(uint32_t))) {
  glProgramUniform1ui(step_.id(), step_.uniform("group_size"), group_size);
}

void GroupsOver::operator()(const Buffer& counts, uint32_t at) {
  glProgramUniform1ui(step_.id(), step_.uniform("at"), at);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counts.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, groups_.id());
  glUseProgram(step_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT);
}

void GroupsOver::dispatch(const Program& program) const { dispatch_indirect(program, groups_); }

}  // namespace plumbago::gpu
