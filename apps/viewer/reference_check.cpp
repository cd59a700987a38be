#include "apps/viewer/reference_check.hpp"

#include <chrono>

namespace plumbago {

ReferenceCheck::~ReferenceCheck() { stop(); }

void ReferenceCheck::stop() {
  if (reference_.valid()) reference_.wait();
  reference_ = {};
  run_.reset();
}

void ReferenceCheck::start(const Scene& scene) {
  stop();
  results_.clear();
  error_.clear();
  run_ = std::make_unique<ParityRun>(scene);
  step_ = 0;
  next_reference();
}

void ReferenceCheck::next_reference() {
  if (step_ == run_->size()) return stop();
  reference_ = std::async(std::launch::async, [run = run_.get(), step = step_] { run->reference(step); });
}

bool ReferenceCheck::poll() {
  if (!running() || reference_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  try {
    reference_.get();
    for (StageParity& s : run_->gpu(step_)) results_.push_back(std::move(s));
    ++step_;
    next_reference();
  } catch (const std::exception& e) {
    error_ = e.what();
    stop();
  }
  return true;
}

double ReferenceCheck::progress() const { return running() ? double(step_) / double(run_->size()) : 1.0; }

Image ReferenceCheck::heatmap(size_t result) const {
  const StageParity& s = results_.at(result);
  return diff_heatmap(s.reference, s.gpu, s.diff.tolerance);
}

}  // namespace plumbago
