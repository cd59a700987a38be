// What the GPU's window-path steps count: see gpu/strokes/row_counts.hpp.
#include "gpu/strokes/row_counts.hpp"

namespace plumbago::gpu {

RowCounts RowCounts::read(const Buffer& buffer) {
  RowCounts c{};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  read_buffer(buffer, &c, sizeof c);
  return c;
}

void RowCounts::add_to(UploadedPaths& table) const {
  table.add_gpu_paths(crease_rows + silhouette_rows, crease_entries + silhouette_entries, crease_entries);
  for (uint32_t style = 0; style < 3; ++style) {  // PathTable::style_of: crease, border, silhouette
    table.gpu_first_round += sum(int(style), 0);
    if (sum(int(style), 1) > 0)
      table.gpu.push_back({style, sum(int(style), 1), sum(int(style), 2), sum(int(style), 3)});
  }
}

}  // namespace plumbago::gpu
