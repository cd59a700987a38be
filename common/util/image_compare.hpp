// Pixel-by-pixel comparison of two images, as every parity test reports it (docs/conventions.md).
#pragma once

#include <string>

#include "common/util/image.hpp"

namespace plumbago {

struct ImageDiff {
  double max_abs = 0;         // largest |a - b| over all pixels and channels
  double rmse = 0;            // root mean square of |a - b| over compared values
  double over_tolerance = 0;  // share of compared pixels with any channel over tolerance
  double tolerance = 0;
  size_t compared = 0;  // pixels compared (after the mask)
};

// Compares `a` and `b` (same size and channels). `mask`, when given, is a 1-channel
// image: only pixels where it is > 0.5 count. Throws std::invalid_argument on a size
// mismatch.
ImageDiff compare_images(const Image& a, const Image& b, double tolerance, const Image* mask = nullptr);

// A heat map of the largest per-channel difference, black = 0, white >= 4 x tolerance,
// red where over tolerance.
Image diff_heatmap(const Image& a, const Image& b, double tolerance);

std::string format_diff(const std::string& name, const ImageDiff& d);

}  // namespace plumbago
