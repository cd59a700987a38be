// What the parity tests check of run_parity's results before they loop over them: the
// names of the comparisons, so that an empty or short result cannot pass.
#pragma once

#include <string>
#include <vector>

#include "apps/parity.hpp"

namespace plumbago::testing {

// The comparisons' names, in order (apps/parity.cpp: each stage's own, in pipeline order).
inline std::vector<std::string> names_of(const std::vector<StageParity>& results) {
  std::vector<std::string> names;
  for (const StageParity& r : results) names.push_back(r.name);
  return names;
}

}  // namespace plumbago::testing
