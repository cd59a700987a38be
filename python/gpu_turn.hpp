// The GPU backend's GL context (gpu/gl/context.hpp: one per process, headless, made on
// first use) serves every Python thread, one call at a time. A GpuTurn makes it current on
// the calling thread while it lives and leaves it current on none when it ends. Take it
// with the GIL released, so that other Python threads run meanwhile.
#pragma once

#include <mutex>
#include <string>

namespace plumbago::python {

class GpuTurn {
 public:
  explicit GpuTurn(bool needed = true);  // needed = false: no turn (the reference backend)
  ~GpuTurn();
  GpuTurn(const GpuTurn&) = delete;
  GpuTurn& operator=(const GpuTurn&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
};

// Refuses (ValueError) a backend other than "gpu" and "reference", naming it; true for "gpu".
bool is_gpu(const std::string& backend);

}  // namespace plumbago::python
