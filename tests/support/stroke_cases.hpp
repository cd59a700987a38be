// What the stroke tests build their hard runs from.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

#include "common/strokes/stroke_style.hpp"

namespace plumbago::testing {

// The default stroke style, `width` px wide, its texture repeating every 48 px.
inline StrokeStyle style_of_width(double width) {
  StrokeStyle s = default_stroke_style();
  s.width_px = float(width);
  s.texture_period_px = 48;
  return s;
}

// n points on `turns` of a circle, from angle 0 (window px).
inline std::vector<glm::dvec2> arc(glm::dvec2 center, double radius, int n, double turns) {
  std::vector<glm::dvec2> p;
  for (int i = 0; i < n; ++i) {
    double a = 2 * std::numbers::pi * turns * i / n;
    p.push_back(center + radius * glm::dvec2(std::cos(a), std::sin(a)));
  }
  return p;
}

}  // namespace plumbago::testing
