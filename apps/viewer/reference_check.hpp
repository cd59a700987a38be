// "Check against the reference": `plumbago compare`'s stage parity (parity/parity.hpp,
// ParityRun) of the current view. The reference half of each step runs in a worker
// thread; the GPU half, short, runs on the viewer's thread between frames, one step a
// frame, so the window stays responsive.
#pragma once

#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "parity/parity.hpp"

namespace plumbago {

class ReferenceCheck {
 public:
  ~ReferenceCheck();
  // Starts a check of `scene`, dropping one under way.
  void start(const Scene& scene);
  // With the GPU context current: when the worker finished a step's reference half, runs
  // its GPU half and starts the next step's. True when there are new results.
  bool poll();
  bool running() const { return run_ != nullptr; }
  double progress() const;  // steps done / steps
  const std::vector<StageParity>& results() const { return results_; }
  const std::string& error() const { return error_; }  // why the last check stopped
  // What `compare --json` prints for the results.
  nlohmann::json report() const { return parity_report(results_); }
  Image heatmap(size_t result) const;

 private:
  void stop();
  void next_reference();
  std::unique_ptr<ParityRun> run_;
  size_t step_ = 0;
  std::future<void> reference_;  // the worker's step_
  std::vector<StageParity> results_;
  std::string error_;
};

}  // namespace plumbago
