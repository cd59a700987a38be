// Silhouette chains, CPU reference (Kalnins et al. 2002, §4.5): the links of
// common/strokes/silhouette_chains.hpp walked one chain at a time, open paths from their
// starts, then each loop from its lowest record.
#include "common/strokes/silhouette_chains.hpp"

#include <bit>
#include <cmath>

#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

// The segments of the table and their links, by record.
struct Segments {
  const Image &facing, &slots, &ends;
  std::vector<glm::uvec4> links;

  bool holds(uint32_t i) const { return facing.data[i] != 0; }
  double window_length(uint32_t i) const {
    const float* e = &ends.data[size_t(i) * 4];
    return std::hypot(double(e[2]) - e[0], double(e[3]) - e[1]);
  }
  int slot(uint32_t i, int end) const { return int(slots.data[size_t(i) * 2 + size_t(end)]); }
  // The segment across the slot that record i leaves by (end 1) or enters by (end 0), when
  // it goes on through that edge the other way with the same facing; kNoLink otherwise.
  uint32_t linked(uint32_t i, int end) const {
    uint32_t link = links[i][slot(i, end)];
    if (link == kNoLink) return kNoLink;
    uint32_t j = link / 4;
    return facing.data[j] == facing.data[i] && slot(j, 1 - end) == int(link % 4) ? j : kNoLink;
  }
};

// The chain from `start`, along the links.
std::vector<uint32_t> chain_from(const Segments& s, uint32_t start) {
  std::vector<uint32_t> members{start};
  for (uint32_t j = s.linked(start, 1); j != kNoLink && j != start; j = s.linked(j, 1)) members.push_back(j);
  return members;
}

// Walks the chain from `start` and writes its rows of the tables.
void walk(const Segments& s, uint32_t start, Image& chains, Image& arcs) {
  std::vector<uint32_t> members = chain_from(s, start);
  bool closed = s.linked(members.back(), 1) == start;
  double length = 0;
  for (uint32_t m : members) length += s.window_length(m);
  double arc = 0;
  for (size_t rank = 0; rank < members.size(); ++rank) {
    float* row = &chains.data[size_t(members[rank]) * 4];
    row[0] = float(start + 1), row[1] = float(rank), row[2] = float(members.size()), row[3] = closed ? 1.0f : 0.0f;
    arcs.data[size_t(members[rank]) * 2] = float(arc), arcs.data[size_t(members[rank]) * 2 + 1] = float(length);
    arc += s.window_length(members[rank]);
  }
}

Segments segments(const ReferenceFrame& f) {
  return {f.get(kSegmentFacing), f.get(kSegmentSlots), f.get(kSegmentEnds), slot_links(f.scene, f.get(kLineMeshes))};
}

// The float error of the GPU's arc lengths (common/strokes/silhouette_chains.hpp): a tree of
// depth d = bit_width(records) sums, 2 (d + 3) u L, where it passes the tolerance.
Image arc_bound(const ReferenceFrame& f) {
  const Image &chains = f.get(kChains), &arcs = f.get(kChainArcs);
  Image bound(arcs.width, arcs.height, 1);
  const double depth = std::bit_width(chains.pixels());
  for (size_t i = 0; i < bound.pixels(); ++i) {
    double b = 2 * (depth + 3) * 0x1p-24 * arcs.data[i * 2 + 1];
    bound.data[i] = b > kArcPx ? float(b) : 0.0f;
  }
  return bound;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(silhouette_chains, [](ReferenceFrame& f) {
  Segments s = segments(f);
  const auto records = uint32_t(s.links.size());
  Image chains = table_image(records, 4), arcs = table_image(records, 2);
  for (uint32_t i = 0; i < records; ++i)  // open paths, from the segment with no predecessor
    if (s.holds(i) && s.linked(i, 0) == kNoLink) walk(s, i, chains, arcs);
  for (uint32_t i = 0; i < records; ++i)  // what is left is loops, each first met at its lowest record
    if (s.holds(i) && chains.data[size_t(i) * 4] == 0) walk(s, i, chains, arcs);
  f.put(kChains, std::move(chains));
  f.put(kChainArcs, std::move(arcs));
});

PLUMBAGO_REFERENCE_BOUND(silhouette_chain_arcs, kChainArcs.name, arc_bound);

}  // namespace plumbago::reference
