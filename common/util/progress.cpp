#include "common/util/progress.hpp"

#include <cstdio>

namespace plumbago {

Progress::Progress(std::string label, size_t total, bool enabled, double delay_s)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      delay_s_(delay_s),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (shown_percent_ >= 0) std::fprintf(stderr, "\r%s: done%10s\n", label_.c_str(), "");
}

void Progress::advance(size_t count) {
  size_t done = done_.fetch_add(count) + count;
  if (!enabled_ || total_ == 0) return;
  std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
  if (elapsed.count() < delay_s_) return;
  std::unique_lock lock(print_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  int percent = int(100.0 * double(done) / double(total_));
  if (percent == shown_percent_) return;
  shown_percent_ = percent;
  std::fprintf(stderr, "\r%s: %3d%% of %zu", label_.c_str(), percent, total_);
  std::fflush(stderr);
}

}  // namespace plumbago
