// Silhouette chains (Kalnins et al. 2002, §4.5): the segments of silhouette_segments joined face to
// face into closed loops and open paths. Like the segments, each backend computes them itself.
//
// Links: a segment links to the segment across the smooth edge it leaves by when that one
// enters through the same edge with the same facing. So a path never crosses a crease or a
// border, and it is cut where the facing changes (as the traced paths of
// common/strokes/feature_lines.hpp). Links go both ways, so every chain is an open path or a
// closed loop, and chains, starts and ranks follow from the links alone: no id depends on
// the order in which work is done.
//   - an open chain starts at its segment without a predecessor, a closed loop at its
//     lowest record;
//   - a segment's rank is its distance from the start along the links.
// The reference walks the links (reference/strokes/silhouette_chains.cpp). The GPU compacts the
// segments and ranks them in parallel by pointer jumping (Wyllie 1979): one round finds
// each loop's lowest record, where the loop is cut, and a second ranks every list both ways
// (gpu/strokes/silhouette_chains.cpp). Fed the same segments, both give the same table.
//
// Output: per face record (common/strokes/silhouette_segments.hpp), (start + 1, rank,
// length, closed), 0 where no segment. Record numbers are exact in a float below 2^24: a
// scene of more faces is refused.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/stage.hpp"
#include "common/strokes/silhouette_segments.hpp"

namespace plumbago {

inline constexpr Buffer kChains{"silhouette_chains.chains"};

// Per record, its slots' links across smooth edges: for slot k, the record across it times 4
// plus its slot there, or kNoLink (a crease, a border, no face there, an object not drawn with
// strokes). View-independent; the fourth entry is unused. Throws std::length_error for a
// scene of 2^24 faces or more.
constexpr uint32_t kNoLink = 0xffffffffu;
std::vector<glm::uvec4> slot_links(const Scene& scene, const LineMeshes& meshes);

// What the tables hold, for Frame::counts: "segments" (records with a segment) and
// "chains" (records of rank 0); none of a table not given (its stage did not run).
std::map<std::string, double> silhouette_counts(const Image* facing, const Image* chains);

struct SilhouetteChainsStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {.name = "silhouette_chains",
            .kind = StageKind::Frame,
            .doc = "silhouette segments chained face to face into loops and open paths (Kalnins et al. 2002, §4.5)",
            .inputs = {{.handle = kLineMeshes}, {.handle = kSegmentFacing}, {.handle = kSegmentSlots}},
            .outputs = {{.handle = kChains,
                         .channels = 4,
                         .doc = "(start + 1, rank, length, closed) per face, 0 where no segment",
                         .tolerance_why = "integers from the same links: exact"}},
            .effects = {"strokes"}};
  }
};

}  // namespace plumbago
