// Silhouette chains, CPU reference (Kalnins et al. 2002, §4.5): the links of
// common/strokes/silhouette_chains.hpp walked one chain at a time, open paths from their
// starts, then each loop from its lowest record.
#include "common/strokes/silhouette_chains.hpp"

#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

// The segments of the table and their links, by record.
struct Segments {
  const Image &facing, &slots;
  std::vector<glm::uvec4> links;

  bool holds(uint32_t i) const { return facing.data[i] != 0; }
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

// Walks the chain from `start` along the links and writes its rows of the table.
void walk(const Segments& s, uint32_t start, Image& chains) {
  std::vector<uint32_t> members{start};
  for (uint32_t j = s.linked(start, 1); j != kNoLink && j != start; j = s.linked(j, 1)) members.push_back(j);
  bool closed = s.linked(members.back(), 1) == start;
  for (size_t rank = 0; rank < members.size(); ++rank) {
    float* row = &chains.data[size_t(members[rank]) * 4];
    row[0] = float(start + 1), row[1] = float(rank), row[2] = float(members.size()), row[3] = closed ? 1.0f : 0.0f;
  }
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(silhouette_chains, [](ReferenceFrame& f) {
  Segments s{f.get(kSegmentFacing), f.get(kSegmentSlots), slot_links(f.scene, f.get(kLineMeshes))};
  const auto records = uint32_t(s.links.size());
  Image chains = table_image(records, 4);
  for (uint32_t i = 0; i < records; ++i)  // open paths, from the segment with no predecessor
    if (s.holds(i) && s.linked(i, 0) == kNoLink) walk(s, i, chains);
  for (uint32_t i = 0; i < records; ++i)  // what is left is loops, each first met at its lowest record
    if (s.holds(i) && chains.data[size_t(i) * 4] == 0) walk(s, i, chains);
  f.put(kChains, std::move(chains));
});

}  // namespace plumbago::reference
