// The viewer's timing panel: fps, the last frame's per-pass times (GL timer queries, as
// `render --stats` reports them) and plots of both over the last seconds.
#pragma once

#include <deque>
#include <vector>

#include "common/core/frame.hpp"

namespace plumbago {

class Timing {
 public:
  // A rendered frame and the wall time it took to render and read back.
  void add(const Frame& frame, double wall_ms);
  // `setup_ms`: what the last new renderer took (Session::setup_ms).
  void draw(double setup_ms) const;

 private:
  struct Sample {
    double at_s, wall_ms;
    std::vector<PassTime> ran;
  };
  void draw_passes(bool preprocessing) const;
  std::vector<float> history(const std::string& pass) const;
  Stopwatch clock_;
  std::deque<Sample> samples_;  // the last kSeconds
};

}  // namespace plumbago
