// What the GPU's window-path steps count: see gpu/strokes/row_counts.hpp.
#include "gpu/strokes/row_counts.hpp"

#include <cstring>

namespace plumbago::gpu {

RowCounts RowCounts::read(const Buffer& buffer, size_t styles) {
  std::vector<uint32_t> all(bytes(styles) / sizeof(uint32_t));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  read_buffer(buffer, all.data(), all.size() * sizeof(uint32_t));  // one read back
  RowCounts c{};
  std::memcpy(static_cast<RowCountsHeader*>(&c), all.data(), sizeof(RowCountsHeader));
  c.sums.assign(all.begin() + sizeof(RowCountsHeader) / sizeof(uint32_t), all.end());
  return c;
}

void RowCounts::add_bounds_to(UploadedPaths& table) const {
  for (uint32_t style = 0; style < sums.size() / 8; ++style) {  // PathTable::style_of
    table.gpu_first_round += sum(style, 0);
    if (sum(style, 1) > 0) table.gpu.push_back({style, sum(style, 1), sum(style, 2), sum(style, 3)});
  }
}

TableRows::TableRows() : header_(Program::compute("strokes/table_rows.comp")) {}

void TableRows::operator()(const Buffer& counts, const UploadedPaths& table) const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counts.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, table.paths.id());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(header_.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace plumbago::gpu
