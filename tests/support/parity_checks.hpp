// What the parity tests check of run_parity's results before they loop over them: the
// names of the comparisons, so that an empty or short result cannot pass.
#pragma once

#include <string>
#include <vector>

#include "parity/parity.hpp"

namespace plumbago::testing {

// The comparisons' names, in order (parity/parity.cpp: the stages in registry order, each
// GPU pass that computes one once, its outputs in declared order).
inline std::vector<std::string> names_of(const std::vector<StageParity>& results) {
  std::vector<std::string> names;
  for (const StageParity& r : results) names.push_back(r.name);
  return names;
}

// The outputs of edge detection and contour lighting, computed in one GPU pass.
inline const std::vector<std::string> kEdgeAndLightResults = {
    "edge_detect.contour_darkness in edge_detect+contour_light",
    "contour_light.lit_contour_darkness in edge_detect+contour_light"};
// The outputs of interior intensity and pencil shading, computed in one GPU pass.
inline const std::vector<std::string> kInteriorResults = {
    "interior_intensity.intensity in interior_intensity+pencil_interior",
    "pencil_interior.interior_darkness in interior_intensity+pencil_interior"};

}  // namespace plumbago::testing
