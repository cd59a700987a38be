// The window paths and runs on the GPU: see gpu/strokes/window_paths.hpp.
#include "gpu/strokes/window_paths.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace plumbago::gpu {

namespace {

// Copies `bytes` of `rows` into `to` from byte `offset` (the buffers are immutable).
void upload(const void* rows, size_t bytes, const ScratchBuffer& to, size_t offset = 0) {
  if (bytes > 0) copy_buffer(make_buffer(rows, bytes), to, bytes, offset);
}

}  // namespace

uint32_t PathTable::style_of(const WindowPath& p) {
  switch (p.kind) {
    case LineKind::Crease:
      return 0;
    case LineKind::Border:
      return 1;
    case LineKind::Silhouette:
      return kSilhouetteStyle;
    case LineKind::Decal:
    case LineKind::Hatching:
      break;
  }
  return 3 + p.decal;
}

PathTable::PathTable(const WindowLines& lines, size_t skip) {
  for (size_t i = skip; i < lines.paths.size(); ++i) {
    const WindowPath& p = lines.paths[i];
    auto n = uint32_t(p.window.size());
    if (n == 0) throw std::logic_error("visibility: a window path has no points");  // window_lines makes none
    VisibilitySample first = sample_at(p, 0);  // its kind and (silhouettes) byte window
    const bool in_ids =
        p.kind == LineKind::Crease || p.kind == LineKind::Border || (p.kind == LineKind::Silhouette && p.front_facing);
    paths.push_back({uint32_t(points.size()), n, entries, first.kind | (p.closed ? 16u : 0u) | (in_ids ? 32u : 0u),
                     first.key, first.byte_window, 0, style_of(p), p.length_px, p.alpha_scale, p.width_scale});
    entries += (p.closed ? n : n - 1) + 1;
    if (p.kind == LineKind::Crease || p.kind == LineKind::Border) silhouette_entry = entries;
    for (uint32_t k = 0; k < n; ++k) {
      const bool segment = p.closed || k + 1 < n;  // to the next point (closed: the last to the first)
      points.push_back({p.window[k], p.arc_px[k], k < p.front_faces.size() ? p.front_faces[k] : glm::uvec2(0),
                        k < p.pressure.size() ? p.pressure[k] : 1.0, p.depth[k],
                        segment ? glm::distance(p.world[k], p.world[(k + 1) % n]) : 0.0, 0.0});
    }
  }
}

RunBound run_bound(const WindowPath& p, double first_round_samples, double width, double height) {
  const double runs = std::floor(first_round_samples / 2) + 1;
  return {PathTable::style_of(p), runs, length_in_margin(p, width, height) + runs, double(p.window.size()) + 2 * runs};
}

uint32_t GpuCount::read() const {
  uint32_t v = 0;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  read_buffer(*buffer, &v, sizeof v, size_t(at) * sizeof(uint32_t));
  return v;
}

Visibility read_runs(const RunTables& tables, const WindowLines& lines) {
  Visibility v;
  if (!tables.runs) return v;
  v.samples = tables.samples.read();
  std::vector<RunRow> rows(tables.listed.read());
  if (rows.size() > tables.bound)
    throw std::logic_error("visibility: " + std::to_string(rows.size()) + " runs over the bound of " +
                           std::to_string(tables.bound));
  if (!rows.empty()) read_buffer(*tables.runs, rows.data(), rows.size() * sizeof(RunRow));
  for (const RunRow& r : rows) v.runs.push_back(run_from_row(lines.paths[r.path], r.path, r.s0, r.s1, r.flags, false));
  return v;
}

glm::uvec3 row_groups(uint32_t count) {
  constexpr uint32_t kGroup = 64, kMaxGroups = 65535;  // shaders/util/rows.glsl kRowsGroup, kMaxGroups
  const uint32_t groups = (count + kGroup - 1) / kGroup, rows = (groups + kMaxGroups - 1) / kMaxGroups;
  return {rows == 0 ? 0 : (groups + rows - 1) / rows, rows, 1};
}

UploadedPaths::UploadedPaths(const WindowLines& lines) {
  PathTable table(lines);
  const size_t point_bytes = table.points.size() * sizeof(PointRow), row_bytes = table.paths.size() * sizeof(PathRow);
  TableHeader h{uint32_t(table.paths.size()), table.entries, table.silhouette_entry};
  for (int k = 0; k < 3; ++k) h.over_entries[k] = row_groups(h.entries)[k], h.over_paths[k] = row_groups(h.paths)[k];
  paths.reserve(sizeof h + row_bytes);
  points.reserve(std::max<size_t>(point_bytes, 1));
  upload(&h, sizeof h, paths);
  upload(table.paths.data(), row_bytes, paths, sizeof h);
  upload(table.points.data(), point_bytes, points);
  path_bound = h.paths, entry_bound = h.entries;
}

void UploadedPaths::reserve(size_t most_paths, size_t most_points) {
  paths.reserve(sizeof(TableHeader) + most_paths * sizeof(PathRow));
  points.reserve(std::max<size_t>(most_points, 1) * sizeof(PointRow));
  gpu_rows = true;
  path_bound = uint32_t(most_paths);
  entry_bound = uint32_t(most_points + most_paths);  // a path's entries: its points, and one
  gpu_first_round = 0, gpu.clear();
}

void UploadedPaths::dispatch(size_t offset) const {
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, paths.id());
  glDispatchComputeIndirect(GLintptr(offset));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

UploadedRuns::UploadedRuns(const WindowLines& lines, const Visibility& visibility) : paths_(lines) {
  std::vector<RunRow> rows;
  for (const WindowPath& p : lines.paths) tables_.bounds.push_back({PathTable::style_of(p), 0, 0, 0});
  for (const VisibleRun& r : visibility.runs) {
    rows.push_back(
        {r.path, uint32_t(r.closed) | uint32_t(r.occluded_start) << 1 | uint32_t(r.occluded_end) << 2, r.s0, r.s1});
    RunBound& b = tables_.bounds.at(r.path);
    b.runs += 1;
    b.length += r.closed ? lines.paths[r.path].length_px : r.s1 - r.s0;
  }
  for (size_t i = 0; i < lines.paths.size(); ++i)
    tables_.bounds[i].points = double(lines.paths[i].window.size()) + 2 * tables_.bounds[i].runs;
  const uint32_t counts[2] = {uint32_t(rows.size()), uint32_t(visibility.samples)};
  runs_ = make_buffer(rows.data(), rows.size() * sizeof(RunRow));
  counts_ = make_buffer(counts, sizeof counts);
  tables_.paths = &paths_.paths.buffer, tables_.points = &paths_.points.buffer, tables_.runs = &runs_;
  tables_.listed = {&counts_, 0}, tables_.samples = {&counts_, 1}, tables_.bound = counts[0];
}

}  // namespace plumbago::gpu
