#version 450 core
// Exclusive prefix sums of a uint buffer (gpu/gl/scan.hpp), one program per step:
//   STEP_SIZE:   one invocation: the count from a buffer on the GPU, the tiles' dispatch;
//   STEP_REDUCE: per tile of 2048 values, their sum;
//   STEP_TILES:  one workgroup: the tiles' sums made the sums of the tiles before each;
//   STEP_DOWN:   per tile, each value replaced by the sum of all values before it;
//   STEP_SINGLE: one workgroup, the values of one tile at most: STEP_DOWN with no tile before.
layout(local_size_x = 256) in;

const uint kPerInvocation = 8u, kTile = 2048u;

layout(std430, binding = 0) buffer Values { uint values[]; };
layout(std430, binding = 1) buffer TileSums { uint tile_sums[]; };
// The dispatch over the tiles (x, 1, 1), then the values' count: the CPU's, or STEP_SIZE's.
layout(std430, binding = 2) buffer Size { uvec4 size; };
#define tiles size.x
#define count size.w

shared uint partial[gl_WorkGroupSize.x];

// The workgroup's exclusive prefix sums of v (Hillis and Steele), and their total.
uint exclusive_scan(uint v, out uint total) {
  const uint t = gl_LocalInvocationID.x, n = gl_WorkGroupSize.x;
  partial[t] = v;
  barrier();
  for (uint d = 1u; d < n; d <<= 1u) {
    uint add = t >= d ? partial[t - d] : 0u;
    barrier();
    partial[t] += add;
    barrier();
  }
  total = partial[n - 1u];
  return partial[t] - v;
}

uint first_of_invocation() { return gl_WorkGroupID.x * kTile + gl_LocalInvocationID.x * kPerInvocation; }

uint invocation_sum() {
  uint sum = 0u;
  for (uint k = 0u, i = first_of_invocation(); k < kPerInvocation; ++k, ++i) sum += i < count ? values[i] : 0u;
  return sum;
}

#if defined(STEP_SIZE)
layout(std430, binding = 3) readonly buffer Counts { uint counts[]; };
uniform uint count_at, scale, capacity;

void main() {
  uint n = min(scale * counts[count_at], capacity - 1u);
  size = uvec4((n + kTile) / kTile, 1u, 1u, n + 1u);
}
#else
void main() {
  uint total;
#if defined(STEP_REDUCE)
  exclusive_scan(invocation_sum(), total);
  if (gl_LocalInvocationID.x == 0u) tile_sums[gl_WorkGroupID.x] = total;
#elif defined(STEP_TILES)  // each invocation a run of consecutive tiles
  uint per = (tiles + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x;
  uint begin = min(tiles, gl_LocalInvocationID.x * per), end = min(tiles, begin + per), sum = 0u;
  for (uint k = begin; k < end; ++k) sum += tile_sums[k];
  uint before = exclusive_scan(sum, total);
  for (uint k = begin; k < end; ++k) {
    uint own = tile_sums[k];
    tile_sums[k] = before;
    before += own;
  }
#elif defined(STEP_DOWN) || defined(STEP_SINGLE)
#if defined(STEP_DOWN)
  uint at = tile_sums[gl_WorkGroupID.x] + exclusive_scan(invocation_sum(), total);
#else
  uint at = exclusive_scan(invocation_sum(), total);
#endif
  for (uint k = 0u, i = first_of_invocation(); k < kPerInvocation && i < count; ++k, ++i) {
    uint own = values[i];
    values[i] = at;
    at += own;
  }
#endif
}
#endif
