// Silhouette paths, CPU reference (Kalnins et al. 2002, §4.5): the chains of the chain table
// laid out in one pass over the records in order (common/strokes/silhouette_paths.hpp).
#include "common/strokes/silhouette_paths.hpp"

#include "common/strokes/strokes.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

struct Tables {
  const Image &chains, &arcs, &facing, &slots, &ends;
  bool keep_back_facing;

  const float* chain(size_t i) const { return &chains.data[i * 4]; }
  // Record i holds a segment of a path the frame draws.
  bool drawn(size_t i) const { return chain(i)[0] != 0 && (keep_back_facing || facing.data[i] > 0); }
};

struct PathRows {
  Image paths, points, crossings;
  size_t path_count = 0, point_count = 0;

  void point(size_t q, glm::vec2 window, float s, float slot, size_t record) {
    float* row = &points.data[q * 3];
    row[0] = window.x, row[1] = window.y, row[2] = s;
    crossings.data[q * 2] = float(record + 1), crossings.data[q * 2 + 1] = slot;
  }
};

// The chain that starts at record `start`: its row, and where its points go.
void add_path(const Tables& t, size_t start, PathRows& out, std::vector<size_t>& first_point) {
  const float* c = t.chain(start);
  const auto points = size_t(c[2]) + (c[3] != 0 ? 0 : 1);
  float* row = &out.paths.data[++out.path_count * 4];
  row[0] = float(start + 1), row[1] = float(out.point_count), row[2] = float(points);
  row[3] = float((c[3] != 0 ? 1 : 0) + (t.facing.data[start] > 0 ? 2 : 0));
  first_point[start] = out.point_count;
  out.point_count += points;
}

// Record i's points: its entry at its rank, and the exit after the last of an open chain.
void add_points(const Tables& t, size_t i, const std::vector<size_t>& first_point, PathRows& out) {
  const float* c = t.chain(i);
  const float *e = &t.ends.data[i * 4], *slot = &t.slots.data[i * 2], *arc = &t.arcs.data[i * 2];
  const size_t q = first_point[size_t(c[0]) - 1] + size_t(c[1]);
  out.point(q, {e[0], e[1]}, arc[0], slot[0], i);
  if (c[3] == 0 && c[1] + 1 == c[2]) out.point(q + 1, {e[2], e[3]}, arc[1], slot[1], i);
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(silhouette_paths, [](ReferenceFrame& f) {
  Tables t{f.get(kChains),       f.get(kChainArcs),   f.get(kSegmentFacing),
           f.get(kSegmentSlots), f.get(kSegmentEnds), f.params<StrokesParams>().keep_back_facing};
  const size_t records = first_faces(f.scene).back();
  PathRows out{table_image(silhouette_path_rows(records), 4), table_image(silhouette_point_rows(records), 3),
               table_image(silhouette_point_rows(records), 2)};
  std::vector<size_t> first_point(records);
  for (size_t i = 0; i < records; ++i)
    if (t.drawn(i) && t.chain(i)[1] == 0) add_path(t, i, out, first_point);
  for (size_t i = 0; i < records; ++i)
    if (t.drawn(i)) add_points(t, i, first_point, out);
  out.paths.data[0] = float(out.path_count), out.paths.data[1] = float(out.point_count);
  f.put(kSilhouettePaths, std::move(out.paths));
  f.put(kSilhouettePoints, std::move(out.points));
  f.put(kSilhouetteCrossings, std::move(out.crossings));
});

}  // namespace plumbago::reference
