// Progress of a long computation on stderr ("curvature (tensor): 42%"). Nothing is
// printed until the computation has run for `delay_s`, so short runs stay silent.
// advance() may be called from any thread.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace plumbago {

class Progress {
 public:
  Progress(std::string label, size_t total, bool enabled, double delay_s = 1.0);
  ~Progress();  // ends the line if anything was printed
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(size_t count);

 private:
  std::string label_;
  size_t total_;
  bool enabled_;
  double delay_s_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<size_t> done_{0};
  std::mutex print_;
  int shown_percent_ = -1;
};

}  // namespace plumbago
