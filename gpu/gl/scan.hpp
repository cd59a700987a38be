// Exclusive prefix sums of a uint buffer on the GPU, in three dispatches (reduce each tile, scan
// the tiles' sums in one workgroup, then each tile with its offset; shaders/util/scan.comp),
// or in one where the values fit one tile of 2048. The count may stay on the GPU: the
// dispatches then go over it indirectly.
#pragma once

#include <cstddef>
#include <cstdint>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class ExclusiveScan {
 public:
  ExclusiveScan();
  // Replaces values[0..n) by the sum of those before each: with a slot appended to n values,
  // values[n] becomes their total.
  void operator()(const Buffer& values, size_t n);
  // The same over values[0..n], n = scale * counts[at] as the GPU holds it (at most
  // capacity - 1): values[n], whatever it held, becomes the total of those before it. The
  // values past n are left as they are.
  void operator()(const Buffer& values, size_t capacity, const Buffer& counts, size_t at, uint32_t scale);

 private:
  void reserve_tiles(size_t n);
  void run(size_t most);  // `most`: the most values, the count's bound

  Program size_, reduce_, tiles_, down_, single_;
  Buffer tile_sums_, size_buffer_;
  size_t tile_capacity_ = 0;
};

}  // namespace plumbago::gpu
