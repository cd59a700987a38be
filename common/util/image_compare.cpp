#include "common/util/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace plumbago {

namespace {

void require_same_shape(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("compare_images: images differ in size or channels (" + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + "x" + std::to_string(a.channels) + " vs " +
                                std::to_string(b.width) + "x" + std::to_string(b.height) + "x" +
                                std::to_string(b.channels) + ")");
}

double pixel_max_diff(const Image& a, const Image& b, size_t i) {
  double m = 0;
  for (int c = 0; c < a.channels; ++c) {
    double d = std::abs(double(a.data[i * a.channels + c]) - double(b.data[i * a.channels + c]));
    m = std::max(m, std::isnan(d) ? INFINITY : d);
  }
  return m;
}

}  // namespace

ImageDiff compare_images(const Image& a, const Image& b, double tolerance, const Image* mask) {
  require_same_shape(a, b);
  ImageDiff d;
  d.tolerance = tolerance;
  double sum_sq = 0;
  size_t over = 0;
  for (size_t i = 0; i < a.pixels(); ++i) {
    if (mask && mask->data[i] <= 0.5f) continue;
    for (int c = 0; c < a.channels; ++c) {
      double e = double(a.data[i * a.channels + c]) - double(b.data[i * a.channels + c]);
      sum_sq += e * e;
    }
    double m = pixel_max_diff(a, b, i);
    d.max_abs = std::max(d.max_abs, m);
    over += m > tolerance;
    ++d.compared;
  }
  if (d.compared) {
    d.rmse = std::sqrt(sum_sq / double(d.compared * a.channels));
    d.over_tolerance = double(over) / double(d.compared);
  }
  return d;
}

Image diff_heatmap(const Image& a, const Image& b, double tolerance) {
  require_same_shape(a, b);
  Image out(a.width, a.height, 3);
  for (size_t i = 0; i < a.pixels(); ++i) {
    double m = pixel_max_diff(a, b, i);
    float v = float(std::min(1.0, m / (4 * tolerance)));
    bool over = m > tolerance;
    out.data[i * 3 + 0] = over ? 1.0f : v;
    out.data[i * 3 + 1] = over ? 0.0f : v;
    out.data[i * 3 + 2] = over ? 0.0f : v;
  }
  return out;
}

std::string format_diff(const std::string& name, const ImageDiff& d) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-16s max_abs %.3g  rmse %.3g  over %.4f%% (tol %.3g, %zu px)", name.c_str(),
                d.max_abs, d.rmse, 100 * d.over_tolerance, d.tolerance, d.compared);
  return buf;
}

}  // namespace plumbago
