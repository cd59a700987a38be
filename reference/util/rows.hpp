// Reference passes loop over pixels; rows may run on several threads (docs/design.md,
// principle 4), each pixel computed exactly as alone.
#pragma once

#include <tbb/parallel_for.h>

namespace plumbago::reference {

// Calls row(y) for y in [0, height), rows in parallel.
template <class Row>
void for_each_row(int height, const Row& row) {
  tbb::parallel_for(0, height, [&](int y) { row(y); });
}

}  // namespace plumbago::reference
