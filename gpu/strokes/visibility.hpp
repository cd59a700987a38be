// Visibility of stroke samples on the GPU (Kalnins et al. 2002, §4.6): the test of common/strokes/visibility.hpp
// on a given batch of samples (shaders/strokes/visibility.comp STEP_TEST), reading back one
// flag per sample. The frame's pass (gpu/strokes/visibility.cpp) samples, tests and bisects
// on the GPU instead; this batch test is how tests and benchmarks reach the formula alone.
#pragma once

#include <cstdint>
#include <vector>

#include "common/strokes/visibility.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class SampleTest {
 public:
  SampleTest();
  // One flag per sample against `ids` (the ID image: RG32UI, key >> 16 and key & 0xffff) and,
  // under strokes.crease_under_silhouettes, `crease_ids` (the same before the silhouettes'
  // quads; else none).
  std::vector<uint8_t> operator()(const Texture& ids, const Texture* crease_ids,
                                  const std::vector<VisibilitySample>& batch);

 private:
  Program program_;
};

}  // namespace plumbago::gpu
