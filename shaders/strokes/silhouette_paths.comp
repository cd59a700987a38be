#version 450 core
// Silhouette paths (Kalnins et al. 2002, §4.5): the chains laid out path by path, the steps of
// gpu/strokes/silhouette_paths.cpp, one program each. The layout is that of
// common/strokes/silhouette_paths.hpp; the loop it replaces is reference/strokes/silhouette_paths.cpp.
// Paths and their points are placed by prefix sums over the records in order (reduce, then
// scan): a tile of 4096 records per workgroup, 16 in a row per invocation.
//   STEP_COUNT:  per tile, its paths and their points;
//   STEP_TILES:  one workgroup: the tiles' sums made exclusive prefixes, and the totals;
//   STEP_PATHS:  per tile, each path's row and where its points start;
//   STEP_POINTS: per record, its points.
#if defined(STEP_POINTS)
layout(local_size_x = 64) in;  // gpu/gl/program.hpp dispatch_in_chunks
#else
layout(local_size_x = 256) in;
#endif

#include "util/common_table.glsl"

const uint kPerInvocation = 16u, kTile = 4096u;

uniform sampler2D chains;  // silhouette_chains.chains: (start + 1, rank, length, closed)
uniform sampler2D arcs;    // silhouette_chains.arcs: (s, L)
uniform sampler2D facing;  // silhouette_segments.facing
uniform sampler2D slots;   // silhouette_segments.slots: (entry, exit)
uniform sampler2D ends;    // silhouette_segments.ends: (x0, y0, x1, y1)
uniform uint records, tiles, first_record;
uniform bool keep_back_facing;

layout(rgba32f, binding = 0) writeonly uniform image2D paths;
layout(rgba32f, binding = 1) writeonly uniform image2D points;
layout(rg32f, binding = 2) writeonly uniform image2D crossings;

// Per tile: (paths, points) it holds; STEP_TILES turns them into those before it.
layout(std430, binding = 0) buffer TileSums { uvec2 tile_sums[]; };
layout(std430, binding = 1) buffer FirstPoints { uint first_point[]; };  // per start record

vec4 chain(uint i) { return texelFetch(chains, table_texel(i), 0); }

// Record i holds a segment of a path the frame draws.
bool drawn(uint i) {
  return i < records && chain(i).x != 0.0 && (keep_back_facing || texelFetch(facing, table_texel(i), 0).r > 0.0);
}

// (1, its points) where record i starts a drawn path, else 0.
uvec2 path_at(uint i) {
  if (!drawn(i) || chain(i).y != 0.0) return uvec2(0u);
  vec4 c = chain(i);
  return uvec2(1u, uint(c.z) + (c.w != 0.0 ? 0u : 1u));
}

shared uvec2 partial[gl_WorkGroupSize.x];

// The workgroup's exclusive prefix sums of v (Hillis and Steele), and their total.
uvec2 exclusive_scan(uvec2 v, out uvec2 total) {
  const uint t = gl_LocalInvocationID.x, n = gl_WorkGroupSize.x;
  partial[t] = v;
  barrier();
  for (uint d = 1u; d < n; d <<= 1u) {
    uvec2 add = t >= d ? partial[t - d] : uvec2(0u);
    barrier();
    partial[t] += add;
    barrier();
  }
  total = partial[n - 1u];
  return partial[t] - v;
}

// This invocation's records in its tile.
uint first_of_invocation() { return gl_WorkGroupID.x * kTile + gl_LocalInvocationID.x * kPerInvocation; }

uvec2 invocation_sum() {
  uvec2 sum = uvec2(0u);
  for (uint k = 0u; k < kPerInvocation; ++k) sum += path_at(first_of_invocation() + k);
  return sum;
}

void main() {
#if defined(STEP_COUNT)
  uvec2 total;
  exclusive_scan(invocation_sum(), total);
  if (gl_LocalInvocationID.x == 0u) tile_sums[gl_WorkGroupID.x] = total;
#elif defined(STEP_TILES)  // one workgroup; each invocation a run of consecutive tiles
  uint per = (tiles + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x;
  uint begin = min(tiles, gl_LocalInvocationID.x * per), end = min(tiles, begin + per);
  uvec2 sum = uvec2(0u), total;
  for (uint k = begin; k < end; ++k) sum += tile_sums[k];
  uvec2 before = exclusive_scan(sum, total);
  for (uint k = begin; k < end; ++k) {
    uvec2 own = tile_sums[k];
    tile_sums[k] = before;
    before += own;
  }
  if (gl_LocalInvocationID.x == 0u) imageStore(paths, table_texel(0u), vec4(total, 0.0, 0.0));
#elif defined(STEP_PATHS)
  uvec2 total;
  uvec2 at = tile_sums[gl_WorkGroupID.x] + exclusive_scan(invocation_sum(), total);
  for (uint k = 0u; k < kPerInvocation; ++k) {
    uint i = first_of_invocation() + k;
    uvec2 here = path_at(i);
    if (here.x == 0u) continue;
    vec4 c = chain(i);
    float flags = (c.w != 0.0 ? 1.0 : 0.0) + (texelFetch(facing, table_texel(i), 0).r > 0.0 ? 2.0 : 0.0);
    imageStore(paths, table_texel(at.x + 1u), vec4(float(i + 1u), float(at.y), float(here.y), flags));
    first_point[i] = at.y;
    at += here;
  }
#elif defined(STEP_POINTS)  // every record, in chunks: its entry at its rank, an open chain's exit after the last
  uint i = first_record + gl_GlobalInvocationID.x;
  if (!drawn(i)) return;
  vec4 c = chain(i), e = texelFetch(ends, table_texel(i), 0), slot = texelFetch(slots, table_texel(i), 0);
  vec2 arc = texelFetch(arcs, table_texel(i), 0).xy;
  uint q = first_point[uint(c.x) - 1u] + uint(c.y);
  imageStore(points, table_texel(q), vec4(e.xy, arc.x, 0.0));
  imageStore(crossings, table_texel(q), vec4(float(i + 1u), slot.x, 0.0, 0.0));
  if (c.w != 0.0 || c.y + 1.0 != c.z) return;
  imageStore(points, table_texel(q + 1u), vec4(e.zw, arc.y, 0.0));
  imageStore(crossings, table_texel(q + 1u), vec4(float(i + 1u), slot.y, 0.0, 0.0));
#endif
}
