// Dispatches over a count the GPU holds, so that a step over what a frame listed runs over
// that many invocations rather than over the bound the CPU sized its buffers by: on llvmpipe
// an invocation past the count still runs its shader's straight-line code, masked off (the
// statue's coherence fit over 52K run slots for ~135 runs: 5.7 ms against 1.6 ms for none).
#pragma once

#include <cstdint>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class GroupsOver {
 public:
  explicit GroupsOver(uint32_t group_size = 64);  // the programs' local_size_x
  // The groups over counts[at] (1 at least, 65535 at most: the steps loop by their grid's
  // stride), written on the GPU. Binds storage buffers 0 and 1.
  void operator()(const Buffer& counts, uint32_t at);
  // Dispatches `program` over them.
  void dispatch(const Program& program) const;

 private:
  Program step_;
  Buffer groups_;
};

}  // namespace plumbago::gpu
