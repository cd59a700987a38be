// Silhouette chains (Kalnins et al. 2002, §4.5): the segments of silhouette_segments joined face to
// face into closed loops and open paths. Like the segments, each backend computes them itself.
//
// Links: a segment links to the segment across the smooth edge it leaves by when that one
// enters through the same edge with the same facing. So a path never crosses a crease or a
// border, and it is cut where the facing changes: the rule of common/strokes/feature_lines.hpp,
// by which the stroke frame's silhouettes are chained. Links go both ways, so every chain is an open path or a
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
// Arc length (Kalnins et al. 2002, §4.5-4.6: strokes are parameterized and sampled by it):
// the window length of each segment (entry to exit) summed along its chain from the start,
// on the GPU in the same pointer-jumping rounds (a prefix sum over a linked list).
//
// Output, per face record (common/strokes/silhouette_segments.hpp), 0 where no segment:
//   - chains: (start + 1, rank, length in segments, closed);
//   - arcs: (s, L), the window arc length at its entry and its chain's whole length (px).
// Record numbers are exact in a float below 2^24: a scene of more faces is refused.
//
// The arcs' parity: float sums in a tree of depth d (the rounds) against the reference's
// sequential double sum: at most (d + 3) u L (u = 2^-24, the lengths' own rounding
// included), doubled; a derived per-record bound where that passes 0.01 px.
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
inline constexpr Buffer kChainArcs{"silhouette_chains.arcs"};
constexpr double kArcPx = 1e-2;  // the arcs' tolerance in px, beyond which the derived bound must explain

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
            .doc =
                "silhouette segments chained face to face into loops and open paths, with their arc length "
                "(Kalnins et al. 2002, §4.5)",
            .inputs = {{.handle = kLineMeshes},
                       {.handle = kSegmentFacing},
                       {.handle = kSegmentSlots},
                       {.handle = kSegmentEnds}},
            .outputs = {{.handle = kChains,
                         .channels = 4,
                         .doc = "(start + 1, rank, length, closed) per face, 0 where no segment",
                         .tolerance_why = "integers from the same links: exact"},
                        {.handle = kChainArcs,
                         .channels = 2,
                         .doc = "(s, L): window arc length at the segment's entry and its chain's length, px",
                         .tolerance = kArcPx,
                         .tolerance_why = "float tree sums against a double sum: beyond 0.01 px, a derived "
                                          "per-record bound of 2 (d + 3) u L"}},
            .effects = {"line_tables"}};
  }
};

}  // namespace plumbago
