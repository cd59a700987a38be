// Exclusive prefix sums of a uint buffer on the GPU: see gpu/gl/scan.hpp.
#include "gpu/gl/scan.hpp"

#include <glm/glm.hpp>
#include <stdexcept>

namespace plumbago::gpu {

namespace {

constexpr size_t kTile = 2048;  // values per workgroup: 256 invocations, 8 in a row each

Program step(const char* name) { return Program::compute("util/scan.comp", std::string("#define ") + name + "\n"); }

size_t tiles_of(size_t n) { return (n + kTile - 1) / kTile; }

// The dispatch and count (x, 1, 1, n): written by the CPU for a count it knows, else by STEP_SIZE.
Buffer make_size_buffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  glBindBuffer(GL_ARRAY_BUFFER, id);
  glBufferStorage(GL_ARRAY_BUFFER, sizeof(glm::uvec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return Buffer(id);
}

}  // namespace

ExclusiveScan::ExclusiveScan()
    : size_(step("STEP_SIZE")),
      reduce_(step("STEP_REDUCE")),
      tiles_(step("STEP_TILES")),
      down_(step("STEP_DOWN")),
      single_(step("STEP_SINGLE")),
      size_buffer_(make_size_buffer()) {}

void ExclusiveScan::reserve_tiles(size_t n) {
  const size_t tiles = tiles_of(n);
  if (tiles > 65535) throw std::length_error("a prefix sum over more than 134 million values");
  if (tiles > tile_capacity_) tile_sums_ = make_buffer(nullptr, tiles * sizeof(uint32_t)), tile_capacity_ = tiles;
}

void ExclusiveScan::operator()(const Buffer& values, size_t n) {
  if (n == 0) return;
  reserve_tiles(n);
  const glm::uvec4 size(tiles_of(n), 1, 1, n);                // the dispatch over the tiles, then the count
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, size_buffer_.id());  // not DSA: OSMesa has no such entry
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof size, &size);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, values.id());
  run(n);
}

void ExclusiveScan::operator()(const Buffer& values, size_t capacity, const Buffer& counts, size_t at, uint32_t scale) {
  if (capacity == 0) return;
  reserve_tiles(capacity);
  glProgramUniform1ui(size_.id(), size_.uniform("count_at"), GLuint(at));
  glProgramUniform1ui(size_.id(), size_.uniform("scale"), scale);
  glProgramUniform1ui(size_.id(), size_.uniform("capacity"), GLuint(capacity));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, values.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, size_buffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, counts.id());
  glUseProgram(size_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  run(capacity);
}

void ExclusiveScan::run(size_t most) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, tile_sums_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, size_buffer_.id());
  if (most <= kTile) {  // one tile: one workgroup, no tile sums
    glUseProgram(single_.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return;
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, size_buffer_.id());
  for (const Program* p : {&reduce_, &tiles_, &down_}) {
    glUseProgram(p->id());
    if (p == &tiles_)
      glDispatchCompute(1, 1, 1);
    else
      glDispatchComputeIndirect(0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

}  // namespace plumbago::gpu
