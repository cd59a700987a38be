// Exclusive prefix sums of a uint buffer on the GPU, in three dispatches (reduce each tile, scan
// the tiles' sums in one workgroup, then each tile with its offset; shaders/util/scan.comp).
#pragma once

#include <cstddef>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class ExclusiveScan {
 public:
  ExclusiveScan();
  // Replaces values[0..n) by the sum of those before each: with a 0 appended to n values,
  // values[n] becomes their total.
  void operator()(const Buffer& values, size_t n);

 private:
  Program reduce_, tiles_, down_;
  Buffer tile_sums_;
  size_t tile_capacity_ = 0;
};

}  // namespace plumbago::gpu
