#include "experiments/shower_door/coherence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "reference/util/sampler.hpp"

namespace plumbago::shower_door {

namespace {

// img at window point q (pixel centers at i + 0.5), channel c (< 4): the GL-exact sampler
// of the reference (reference/util/sampler.hpp), edges clamped.
float read(const Image& img, float qx, float qy, int c, Sampling sampling) {
  const reference::SamplerState state{sampling == Sampling::Nearest ? reference::Filter::Nearest
                                                                    : reference::Filter::Linear};
  return reference::sample(img, glm::vec2(qx / float(img.width), qy / float(img.height)), state)[c];
}

}  // namespace

double Residuals::coherence() const {
  double sum = attached + fixed;
  return pixels == 0 || sum == 0 ? std::numeric_limits<double>::quiet_NaN() : fixed / sum;
}

Image residual_map(const Image& prev, const Image& next, const Image& motion, Sampling sampling) {
  if (prev.width != next.width || prev.height != next.height || prev.channels != next.channels ||
      motion.width != next.width || motion.height != next.height || motion.channels != 3 || next.channels > 4)
    throw std::invalid_argument(
        "shower_door: patterns and motion map differ in size or channels, or a pattern has over 4");
  Image out(next.width, next.height, 2);
  for (int y = 0; y < next.height; ++y)
    for (int x = 0; x < next.width; ++x) {
      if (motion.at(x, y, 2) == 0.0f) continue;
      float qx = motion.at(x, y, 0), qy = motion.at(x, y, 1);
      double a = 0, b = 0;
      for (int c = 0; c < next.channels; ++c) {
        double now = next.at(x, y, c);
        a += std::pow(now - read(prev, qx, qy, c, sampling), 2);
        b += std::pow(now - prev.at(x, y, c), 2);
      }
      out.at(x, y, 0) = float(std::sqrt(a)), out.at(x, y, 1) = float(std::sqrt(b));
    }
  return out;
}

Residuals residuals(const Image& prev, const Image& next, const Image& motion, Sampling sampling) {
  Image map = residual_map(prev, next, motion, sampling);
  Residuals r;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      if (motion.at(x, y, 2) == 0.0f) continue;
      r.attached += map.at(x, y, 0);
      r.fixed += map.at(x, y, 1);
      ++r.pixels;
    }
  if (r.pixels > 0) r.attached /= double(r.pixels), r.fixed /= double(r.pixels);
  return r;
}

}  // namespace plumbago::shower_door
