// The window paths and visible runs as the GPU's stroke steps read them: the rows of
// shaders/strokes/window_paths.glsl (std430). The ID image pass uploads the paths and draws its
// lines from them (gpu/strokes/id_lines.hpp); the visibility pass samples them and lists the
// runs on the GPU (gpu/strokes/visibility.cpp) and shares them with the stroke pass, which
// makes each run's window polyline there (gpu/strokes/stroke_samples.hpp); where the runs were
// found elsewhere (parity feeds the reference's), UploadedRuns puts them up.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/handle.hpp"
#include "common/strokes/visibility.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

struct PathRow {
  uint32_t first_point, points, first_entry, kind, key, byte_window, sampled, style;
  double length_px, alpha_scale, width_scale;
};
struct PointRow {
  glm::dvec2 window;
  double s;
  glm::uvec2 faces;
  double pressure, depth, world_step, pad;  // std430: a dvec2's struct is 16-aligned
};
struct RunRow {
  uint32_t path, flags;  // common/strokes/visibility.hpp run_tables' flags
  double s0, s1;
};
static_assert(sizeof(PathRow) == 56 && sizeof(PointRow) == 64 && sizeof(RunRow) == 24,
              "std430 layouts of window_paths.glsl");

// The paths of `lines` as rows, but their first `skip` (the GPU's own, made elsewhere); each
// path's entries (visibility.comp) are its segments and its end.
// A path's kind: its sample kind (common/strokes/visibility.hpp), + 16 closed, + 32 drawn in
// the ID image (common/strokes/id_image.hpp: creases, borders and front-facing silhouettes).
// A path's style: its line kind's (crease 0, border 1, silhouette 2), or its decal's, 3 + d
// (gpu/strokes/run_styles.hpp).
struct PathTable {
  explicit PathTable(const WindowLines& lines, size_t skip = 0);
  static uint32_t style_of(const WindowPath& p);
  static constexpr uint32_t kSilhouetteStyle = 2;
  std::vector<PathRow> paths;
  std::vector<PointRow> points;
  uint32_t entries = 0;
  uint32_t silhouette_entry = 0;  // the entries of the creases and borders, which come first
};

// What the CPU sizes the visibility and stroke buffers by, for one path or for several
// together: the most runs (from the first-round samples' bound S: a run holds a visible sample
// and a hidden one parts two runs, so floor(S / 2) + 1 at most), their most length together
// (the length within the window's margin, common/strokes/visibility.hpp length_in_margin, and
// 1 px a run), and the most points their polylines take (each path point in one run at most,
// and a run's two ends).
struct RunBound {
  uint32_t style = 0;  // PathTable::style_of
  double runs = 0, length = 0, points = 0;
};
RunBound run_bound(const WindowPath& p, double first_round_samples, double width, double height);

// A path table's header, before its rows (strokes/window_paths.glsl, std430): how many paths
// and entries it holds, its first silhouette entry, and the indirect dispatches over its
// entries and over its paths, (x, y, 1) groups of 64 (row_groups).
struct TableHeader {
  uint32_t paths = 0, entries = 0, silhouette_entry = 0, pad = 0;
  uint32_t over_entries[3] = {0, 0, 0}, over_paths[3] = {0, 0, 0}, pad2[2] = {0, 0};
};
static_assert(sizeof(TableHeader) == 48, "std430 layout of window_paths.glsl Paths' header");
// The (x, y, 1) groups of 64 rows over `count` rows (shaders/util/rows.glsl row_groups).
glm::uvec3 row_groups(uint32_t count);

// A frame's path table on the GPU, put up once: the ID image draws its lines from it
// (gpu/strokes/id_lines.hpp), the visibility steps sample it, the stroke steps follow it.
// Its paths are in the order of the window lines (common/strokes/strokes.hpp: creases and
// borders, silhouettes, decals and hatches). Either the CPU puts up every row (the lines a
// backend was fed: parity), or the GPU writes them (gpu/strokes/crease_rows.hpp,
// silhouette_rows.hpp, decal_rows.hpp) and the table's header (gpu/strokes/row_counts.hpp
// TableRows), so that the CPU knows the table by its bounds alone: the steps over its rows go
// by the header's dispatches.
struct UploadedPaths {
  UploadedPaths() = default;
  explicit UploadedPaths(const WindowLines& lines);  // every path from the CPU, the header too
  // Room for a table the GPU writes: `paths` paths and `points` points at most. The buffers
  // are kept where they hold that.
  void reserve(size_t paths, size_t points);
  // A dispatch of the program in use over the table's entries, or over its paths.
  void dispatch_over_entries() const { dispatch(offsetof(TableHeader, over_entries)); }
  void dispatch_over_paths() const { dispatch(offsetof(TableHeader, over_paths)); }
  ScratchBuffer paths, points;               // paths: the header, then the rows
  bool gpu_rows = false;                     // whether the GPU writes the rows (reserve)
  uint32_t path_bound = 0, entry_bound = 0;  // the most the table holds: what the steps size by
  // Whether the CPU knows the GPU's paths' bounds this frame (it read them back: a frame that
  // sizes the buffers, gpu/core/pipeline.hpp): their first-round samples' bound, together, and
  // their run bounds, per line style. Else the steps go by the buffers an earlier frame sized.
  bool sized = true;
  double gpu_first_round = 0;
  std::vector<RunBound> gpu;

 private:
  void dispatch(size_t offset) const;
};
inline constexpr Shared<UploadedPaths> kPathTable{"id_image.path_table"};

// A GPU count: the uint at `at` of `buffer`.
struct GpuCount {
  const Buffer* buffer = nullptr;
  uint32_t at = 0;
  uint32_t read() const;
};

// The runs of a frame on the GPU: the paths' rows and points, the run rows, how many are
// listed and how many first-round visibility samples found them, both on the GPU. What the
// CPU knows: the most runs the rows hold, and (where `sized`, UploadedPaths::sized) the
// paths' run bounds.
struct RunTables {
  const Buffer *paths = nullptr, *points = nullptr, *runs = nullptr;
  GpuCount listed, samples;
  uint32_t bound = 0;
  bool sized = true;
  std::vector<RunBound> bounds;  // per CPU path, then the GPU's paths together
};
inline constexpr Shared<RunTables> kRunTables{"visibility.run_tables"};

// The runs read back (a frame never does: for dumps, a frame's counts and tests), as
// run_from_row makes them, without their polylines; `samples` as listed. Throws
// std::logic_error where the GPU counted more than the rows hold.
Visibility read_runs(const RunTables& tables, const WindowLines& lines);

// The runs of `visibility` over `lines`, put up as the visibility pass leaves them.
class UploadedRuns {
 public:
  UploadedRuns(const WindowLines& lines, const Visibility& visibility);
  const RunTables& tables() const { return tables_; }

 private:
  UploadedPaths paths_;
  Buffer runs_, counts_;
  RunTables tables_;
};

}  // namespace plumbago::gpu
