#include "python/gpu_turn.hpp"

#include <stdexcept>

#include "gpu/gl/context.hpp"

namespace plumbago::python {
namespace {

std::mutex& gpu_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

GpuTurn::GpuTurn(bool needed) {
  if (!needed) return;
  lock_ = std::unique_lock<std::mutex>(gpu_mutex());
  gpu::Context::get().make_current();
}

GpuTurn::~GpuTurn() {
  if (!lock_.owns_lock()) return;
  try {
    gpu::Context::get().release();
  } catch (const std::runtime_error&) {  // still current here: the next turn's make_current says why
  }
}

bool is_gpu(const std::string& backend) {
  if (backend != "gpu" && backend != "reference")
    throw std::invalid_argument("backend: '" + backend + "' is neither gpu nor reference");
  return backend == "gpu";
}

}  // namespace plumbago::python
