// Exclusive prefix sums of a uint buffer on the GPU: see gpu/gl/scan.hpp.
#include "gpu/gl/scan.hpp"

#include <stdexcept>

namespace plumbago::gpu {

namespace {

constexpr size_t kTile = 2048;  // values per workgroup: 256 invocations, 8 in a row each

Program step(const char* name) { return Program::compute("util/scan.comp", std::string("#define ") + name + "\n"); }

}  // namespace

ExclusiveScan::ExclusiveScan() : reduce_(step("STEP_REDUCE")), tiles_(step("STEP_TILES")), down_(step("STEP_DOWN")) {}

void ExclusiveScan::operator()(const Buffer& values, size_t n) {
  if (n == 0) return;
  const size_t tiles = (n + kTile - 1) / kTile;
  if (tiles > 65535) throw std::length_error("a prefix sum over more than 134 million values");
  if (tiles > tile_capacity_) tile_sums_ = make_buffer(nullptr, tiles * sizeof(uint32_t)), tile_capacity_ = tiles;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, values.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, tile_sums_.id());
  for (const Program* p : {&reduce_, &tiles_, &down_}) {
    glProgramUniform1ui(p->id(), p->uniform("count"), GLuint(n));
    glProgramUniform1ui(p->id(), p->uniform("tiles"), GLuint(tiles));
    glUseProgram(p->id());
    glDispatchCompute(p == &tiles_ ? 1 : GLuint(tiles), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

}  // namespace plumbago::gpu
