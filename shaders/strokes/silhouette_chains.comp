#version 450 core
// Silhouette chains (Kalnins et al. 2002, §4.5) by pointer jumping (Wyllie 1979): the steps of
// gpu/strokes/silhouette_chains.cpp, one program each (STEP_LINK, STEP_ARGS, STEP_LOOPS,
// STEP_CUT, STEP_RANK, STEP_WRITE). The links are those of common/strokes/silhouette_chains.hpp;
// the walk they replace is reference/strokes/silhouette_chains.cpp.
layout(local_size_x = 64) in;

#include "util/common_table.glsl"

const uint kNoLink = 0xffffffffu;

layout(std430, binding = 0) readonly buffer SlotLinks { uvec4 slot_links[]; };  // per record
// Per record: (successor, predecessor, closed, -), kNoLink where none.
layout(std430, binding = 1) buffer Links { uvec4 links[]; };
layout(std430, binding = 2) buffer Members { uint members[]; };  // the records that hold a segment
// How many members, the indirect dispatch over them all, and round k's of each phase: while
// 2^k < count (a chain is no longer than the count), over the members round k - 1 left
// active (below), all of them in round 0; else none. Over them all is all_x x all_y groups,
// all_x at most GL's least maximum of 65535 (member() flattens them). Each phase also stops
// after a round that changed nothing it decides by: ranking, no pointer moved (that round
// wrote what it read); finding loops, no mark changed (below: round k works only where
// round k - 1 marked it). Both buffers then hold the result, whichever the steps after it read.
layout(std430, binding = 3) buffer Count {
  uint count;
  uint all_x, all_y, all_z;  // not a uvec3: std430 would align it to 16 bytes
  uvec4 round_groups[32];
  uvec4 rank_groups[32];
  uint loop_active[32], rank_active[32];  // round k's members (k > 0), listed in Active's half k % 2
  uint loop_marked[32];                   // whether round k - 1 changed a mark
};
// Pointer jumping between the two halves of each buffer below, each step reading one and
// writing the other: finding loops, (next, mark, -, -); ranking, (start, rank, end, distance
// to it), and the arc lengths below. A record's mark is the least over the records from it to
// its `next` (not included) of their keys: record + 1, 0 for an open chain's end. After the
// rounds a loop's members hold its lowest record + 1 (where it is cut) and an open chain's 0,
// their `next` its end. The marks are minima over windows that double each round: a round
// that changes none changes none after it (where every mark at k is at most the one 2^k
// further on, so is each at 2k), so each open chain's marks are 0 already, its windows and
// `next` at its end.
layout(std430, binding = 4) buffer Jump { uvec4 jump[]; };  // half h from h * records
// Ranking's window arc lengths alongside, the same way: (before, after), the lengths of the
// segments before it and after it in its list.
layout(std430, binding = 5) buffer Arc { vec2 arc[]; };  // half h from h * records
// Each phase's active members: those whose value a round changed, which the next round works
// on. One whose value did not change is final, wrote the value it read, so both halves hold
// it, and the rounds after can leave it out and still read it in either half. Ranking: its
// pointers did not move, so they are at its chain's start and end, and nothing is added to
// its rank, distance or arc lengths there. Finding loops: its `next` did not move, so that is
// an open chain's end, which points at itself with mark 0, and its mark, unchanged, is 0.
layout(std430, binding = 6) buffer Active { uint actives[]; };  // round k's in half k % 2, from (k % 2) * records
uniform uint round_index;  // k, of this phase's rounds
uniform uint rounds;       // issued per phase
uniform uint records, first_record;

// The rounds that do work, R: those with 2^k < count (Count above). The link step writes
// half 0; round k of the first phase reads k % 2, so the cut reads R % 2 and writes the
// other, round k of the second phase reads (R + 1 + k) % 2, and the last step reads 1.
uint working_rounds() { return min(rounds, count > 1u ? uint(findMSB(count - 1u)) + 1u : 0u); }
uint source() {
#if defined(STEP_LOOPS)
  return round_index % 2u;
#elif defined(STEP_CUT)
  return working_rounds() % 2u;
#elif defined(STEP_RANK)
  return (working_rounds() + 1u + round_index) % 2u;
#else
  return 1u;  // the link step writes half 0; the last step reads half 1
#endif
}
// Where a step reads and writes: source()'s half and the other, found once per invocation
// (main), not in every access (source() reads `count`).
struct Halves {
  uint from, to;
};
Halves halves() {
  uint from = source();
  return Halves(from * records, (1u - from) * records);
}
uvec4 src(Halves h, uint i) { return jump[h.from + i]; }
void put(Halves h, uint i, uvec4 v) { jump[h.to + i] = v; }
vec2 arc_src(Halves h, uint i) { return arc[h.from + i]; }
void arc_put(Halves h, uint i, vec2 v) { arc[h.to + i] = v; }

uniform sampler2D facing;  // silhouette_segments.facing
uniform sampler2D slots;   // silhouette_segments.slots (entry, exit)
uniform sampler2D ends;    // silhouette_segments.ends
layout(rgba32f, binding = 0) writeonly uniform image2D chains;
layout(rg32f, binding = 1) writeonly uniform image2D arcs;

float facing_of(uint i) { return texelFetch(facing, table_texel(i), 0).r; }
int slot_of(uint i, int end) { return int(texelFetch(slots, table_texel(i), 0)[end]); }
float length_of(uint i) {
  vec4 e = texelFetch(ends, table_texel(i), 0);
  return distance(e.xy, e.zw);
}

// The segment across the slot record i leaves by (end 1) or enters by (end 0), when it goes
// on through that edge the other way with the same facing.
uint linked(uint i, int end) {
  uint link = slot_links[i][slot_of(i, end)];
  if (link == kNoLink) return kNoLink;
  uint j = link / 4u;
  return facing_of(j) == facing_of(i) && slot_of(j, 1 - end) == int(link % 4u) ? j : kNoLink;
}

#if defined(STEP_LOOPS)
#define ACTIVE loop_active
#define GROUPS round_groups
#elif defined(STEP_RANK)
#define ACTIVE rank_active
#define GROUPS rank_groups
#endif

// The member this invocation works on, or kNoLink past the count: of them all, or in a
// round after a phase's first, of those the round before left active.
uint member() {
  uint m = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
#if defined(ACTIVE)
#if defined(STEP_LOOPS)
  if (round_index > 0u && loop_marked[round_index] == 0u) return kNoLink;
#endif
  if (round_index > 0u) return m < ACTIVE[round_index] ? actives[(round_index % 2u) * records + m] : kNoLink;
#endif
  return m < count ? members[m] : kNoLink;
}

const uint kMaxGroups = 65535u;  // GL's least maximum of work groups in x

#if defined(ACTIVE)
// Member i is listed active for this phase's round k, whose groups grow to cover it.
void activate(uint i, uint k) {
  uint at = atomicAdd(ACTIVE[k], 1u);
  actives[(k % 2u) * records + at] = i;
  if (at % 64u != 0u) return;
  uint groups = at / 64u + 1u;
  atomicMax(GROUPS[k].x, min(groups, kMaxGroups));
  atomicMax(GROUPS[k].y, (groups + kMaxGroups - 1u) / kMaxGroups);
}
#endif

void main() {
  Halves h = halves();
#if defined(STEP_LINK)  // every record, in chunks: links, the members, and the loop search's start
  uint i = first_record + gl_GlobalInvocationID.x;
  if (i >= records) return;
  if (facing_of(i) == 0.0) {  // no member: its rows 0 (STEP_WRITE writes the members')
    imageStore(chains, table_texel(i), vec4(0.0));
    imageStore(arcs, table_texel(i), vec4(0.0));
    return;
  }
  uint next = linked(i, 1);
  links[i] = uvec4(next, linked(i, 0), 0u, 0u);
  members[atomicAdd(count, 1u)] = i;
  put(h, i, next == kNoLink ? uvec4(i, 0u, 0u, 0u) : uvec4(next, i + 1u, 0u, 0u));
#elif defined(STEP_ARGS)  // one invocation
  if (gl_GlobalInvocationID.x != 0u) return;
  uint groups = (count + 63u) / 64u;
  all_y = (groups + kMaxGroups - 1u) / kMaxGroups;
  all_x = all_y > 1u ? kMaxGroups : groups;
  all_z = 1u;
  for (uint k = 0u; k < 32u; ++k) {
    uint first = k == 0u && count > 1u ? all_x : 0u;  // later ones: activate()
    round_groups[k] = rank_groups[k] = uvec4(first, first > 0u ? all_y : 0u, 1u, 0u);
  }
#elif defined(STEP_LOOPS)  // next <- next of next, mark <- the lower of both
  uint i = member();
  if (i == kNoLink) return;
  uvec4 here = src(h, i), there = src(h, here.x);
  uvec4 moved = uvec4(there.x, min(here.y, there.y), 0u, 0u);
  put(h, i, moved);
  uint k = round_index + 1u;
  if (moved == here || k >= 32u || count <= (1u << k)) return;
  activate(i, k);
  if (moved.y != here.y) loop_marked[k] = 1u;
#elif defined(STEP_CUT)  // a loop is cut before its lowest record: every chain is a list both ways
  uint i = member();
  if (i == kNoLink) return;
  uvec4 found = src(h, i), l = links[i];
  // An open chain's `next` is its end, which has no successor; a loop's mark its lowest + 1.
  bool closed = links[found.x].x != kNoLink;
  uint cut = found.y;
  bool first = l.y == kNoLink || (closed && i + 1u == cut), last = l.x == kNoLink || (closed && l.x + 1u == cut);
  links[i].z = closed ? 1u : 0u;
  put(h, i, uvec4(first ? i : l.y, first ? 0u : 1u, last ? i : l.x, last ? 0u : 1u));
  arc_put(h, i, vec2(first ? 0.0 : length_of(l.y), last ? 0.0 : length_of(l.x)));
#elif defined(STEP_RANK)  // both ways: start and rank, end and distance to it
  uint i = member();
  if (i == kNoLink) return;
  uvec4 here = src(h, i), back = src(h, here.x), ahead = src(h, here.z);
  uvec4 jumped = uvec4(back.x, here.y + back.y, ahead.z, here.w + ahead.w);
  put(h, i, jumped);
  arc_put(h, i, vec2(arc_src(h, i).x + arc_src(h, here.x).x, arc_src(h, i).y + arc_src(h, here.z).y));
  // Only a start and an end point at themselves, with rank and distance 0 (and s 0): a
  // member whose pointers did not move is done.
  uint k = round_index + 1u;
  if (jumped != here && k < 32u && count > (1u << k)) activate(i, k);
#elif defined(STEP_WRITE)
  uint i = member();
  if (i == kNoLink) return;
  uvec4 ranked = src(h, i);
  imageStore(chains, table_texel(i), vec4(ranked.x + 1u, ranked.y, ranked.y + ranked.w + 1u, links[i].z));
  vec2 arc = arc_src(h, i);
  imageStore(arcs, table_texel(i), vec4(arc.x, arc.x + length_of(i) + arc.y, 0.0, 0.0));
#endif
}
