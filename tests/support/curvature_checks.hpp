// What every curvature result must satisfy (Lee et al. 2006, §5.3; Alliez et al. 2003), for the curvature tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "common/curvature/curvature.hpp"

namespace plumbago::testing {

// The curvature parameters: defaults with "curvature.name=value" overrides.
inline CurvatureParams curvature_params(const std::vector<std::string>& assignments = {}) {
  ParamSet set;
  for (const auto& a : assignments) set.set_assignment(a);
  return set.get<CurvatureParams>();
}

inline bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// One entry per vertex, nothing NaN or Inf, k_min <= k_max, normal and directions unit,
// directions tangent and orthogonal. Reports the first vertex that fails.
inline void expect_valid_curvature(const Curvature& c, size_t vertices, const std::string& what) {
  ASSERT_EQ(c.k_min.size(), vertices) << what;
  ASSERT_EQ(c.k_max.size(), vertices) << what;
  ASSERT_EQ(c.normal.size(), vertices) << what;
  ASSERT_EQ(c.d_min.size(), vertices) << what;
  ASSERT_EQ(c.d_max.size(), vertices) << what;
  const float tol = 1e-4f;
  for (size_t v = 0; v < vertices; ++v) {
    bool ok = std::isfinite(c.k_min[v]) && std::isfinite(c.k_max[v]) && c.k_min[v] <= c.k_max[v] &&
              finite3(c.normal[v]) && finite3(c.d_min[v]) && finite3(c.d_max[v]) &&
              std::abs(glm::length(c.normal[v]) - 1) < tol && std::abs(glm::length(c.d_min[v]) - 1) < tol &&
              std::abs(glm::length(c.d_max[v]) - 1) < tol && std::abs(glm::dot(c.d_min[v], c.normal[v])) < tol &&
              std::abs(glm::dot(c.d_max[v], c.normal[v])) < tol && std::abs(glm::dot(c.d_min[v], c.d_max[v])) < tol;
    ASSERT_TRUE(ok) << what << ": vertex " << v << " k " << c.k_min[v] << " " << c.k_max[v] << " n (" << c.normal[v].x
                    << " " << c.normal[v].y << " " << c.normal[v].z << ") d_min (" << c.d_min[v].x << " "
                    << c.d_min[v].y << " " << c.d_min[v].z << ")";
  }
}

}  // namespace plumbago::testing
