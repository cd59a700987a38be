// Silhouette paths (Kalnins et al. 2002, §4.5): the chains of silhouette_chains laid out path
// after path, the points of each in order, as the stroke frame draws them. Each backend
// computes them itself from its chain table; the GPU's stroke frame reads its own.
//
// Which chains: the front-facing ones, and the back-facing ones too under
// strokes.keep_back_facing. Paths are in the order of their start records (their chain's
// start: common/strokes/silhouette_chains.hpp), so a path's place follows from the links
// alone, as its key does (common/strokes/strokes.hpp: silhouette_base + start record).
// A path's points are its crossings: each member's entry in rank order, then an open
// chain's last exit; point k lies at arc length s = the arcs table's s of member k (the
// exit: the chain's length L).
//
// Layout (common/util/image.hpp tables, kTableRow records a row):
//   - paths, records + 1 rows: row 0 holds the counts (paths, points, 0, 0); row 1 + p
//     path p: (start record + 1, its first point, its points, closed + 2 front-facing);
//   - points, 2 records rows (an open chain of one segment has two): row q, point q of
//     the paths in order: (x, y, s), its window position and arc length (px);
//   - crossings, as many rows: (record + 1, slot), the face it lies on (the member whose
//     entry it is, the last member for an exit) and the slot of that face: where the GPU
//     places each point in double (gpu/strokes/silhouette_points.hpp).
// Unused rows are 0. The GPU counts and places them with prefix sums over the records
// (gpu/strokes/silhouette_paths.cpp), the reference in one loop in record order
// (reference/strokes/silhouette_paths.cpp). Fed the same chains, both give the same tables:
// they copy and order what the chains hold.
#pragma once

#include <cstdint>
#include <vector>

#include "common/core/stage.hpp"
#include "common/strokes/silhouette_chains.hpp"

namespace plumbago {

inline constexpr Buffer kSilhouettePaths{"silhouette_paths.paths"};
inline constexpr Buffer kSilhouettePoints{"silhouette_paths.points"};
inline constexpr Buffer kSilhouetteCrossings{"silhouette_paths.crossings"};

// The table sizes for `records` face records.
constexpr size_t silhouette_path_rows(size_t records) { return records + 1; }
constexpr size_t silhouette_point_rows(size_t records) { return 2 * records; }

// A path point where a backend placed it (the GPU: gpu/strokes/silhouette_points.hpp): the
// window position and linear view depth of the crossing on its face's slot, p = a + (b - a) t
// (Kalnins et al. 2002, §4.5, common/strokes/feature_lines.hpp), in double. The GPU's
// layout (std430).
struct SilhouettePoint {
  double x, y, depth, t;
  uint32_t record, slot;
};
static_assert(sizeof(SilhouettePoint) == 40);

// The paths of the tables' rows `paths` (4 channels, from row 0, as many as its counts say),
// their points `points` in order: each point's surface point is the one at t on its face's
// slot, its window position and depth the backend's.
std::vector<ChainPath> chain_paths(const Scene& scene, const LineMeshes& meshes, const std::vector<float>& paths,
                                   const std::vector<SilhouettePoint>& points);

struct SilhouettePathsStage {
  using Params = TypeList<>;  // reads strokes.keep_back_facing, which the ID image declares
  static StageDesc describe() {
    return {.name = "silhouette_paths",
            .kind = StageKind::Frame,
            .doc = "the silhouette chains laid out path by path, their points in order (Kalnins et al. 2002, §4.5)",
            .params = {"strokes"},
            .inputs = {{.handle = kChains},
                       {.handle = kChainArcs},
                       {.handle = kSegmentFacing},
                       {.handle = kSegmentSlots},
                       {.handle = kSegmentEnds}},
            .outputs = {{.handle = kSilhouettePaths,
                         .channels = 4,
                         .doc = "row 0 (paths, points); row 1 + p: (start record + 1, first point, points, closed + "
                                "2 front)",
                         .tolerance_why = "integers from the same chains: exact"},
                        {.handle = kSilhouettePoints,
                         .channels = 3,
                         .doc = "per path point in order: (x, y, s): window position and arc length (px)",
                         .tolerance_why = "copied from the same segments and arcs: exact"},
                        {.handle = kSilhouetteCrossings,
                         .channels = 2,
                         .doc = "per path point: (record + 1, slot), the face it lies on and that face's slot",
                         .tolerance_why = "integers from the same chains: exact"}},
            .effects = {"line_tables"}};
  }
};

}  // namespace plumbago
