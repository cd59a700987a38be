// What the parity tests check of run_parity's results before they loop over them: the
// names of the comparisons, so that an empty or short result cannot pass.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
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

// A table stage's parity on `scene`: its outputs by name, each printed with what its derived
// bound allowed and expected to pass.
inline std::vector<StageParity> table_parity(const Scene& scene, const std::string& stage,
                                             const std::vector<std::string>& outputs, const std::string& label) {
  std::vector<StageParity> results = run_parity(scene, {stage});
  EXPECT_EQ(names_of(results), outputs) << label;
  for (const StageParity& r : results) {
    std::printf("[%s %s] %s  bound allows %zu  [%s]\n", stage.c_str(), label.c_str(),
                format_diff(r.name, r.diff).c_str(), r.bounded, r.note.c_str());
    EXPECT_TRUE(r.pass) << label << " " << r.name << ": " << r.note;
  }
  return results;
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
