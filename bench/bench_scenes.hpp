// Scenes the benchmarks share: the shared models at 800x800 (skipped when absent) and
// the built-in CAD part.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"

namespace plumbago::bench {

inline std::vector<std::string> bench_models() { return {"fandisk.obj", "stanford-bunny.obj", "ogre.obj"}; }

// The shared models' folder: $PLUMBAGO_MODELS_DIR, else ../shared/models of the source tree.
inline std::string models_dir() {
  const char* env = std::getenv("PLUMBAGO_MODELS_DIR");
  return env && *env ? env : PLUMBAGO_MODELS_DIR;
}

// Returns false (and marks the benchmark skipped) when the model is not there.
inline bool load_bench_scene(benchmark::State& state, const std::string& model, Scene& scene) {
  std::string dir = models_dir();
  if (!std::filesystem::exists(dir + "/" + model)) {
    state.SkipWithError(("../shared/models/" + model + " is not here").c_str());
    return false;
  }
  scene = parse_scene("{\"mesh\": \"" + model + "\", \"resolution\": [800, 800]}", "bench:" + model, dir);
  return true;
}

// Registers `fn` once per shared model, named BASE/<model stem>.
template <class Fn>
void register_per_model(const std::string& base, Fn fn) {
  for (const std::string& model : bench_models()) {
    std::string stem = std::filesystem::path(model).stem().string();
    benchmark::RegisterBenchmark((base + "/" + stem).c_str(), [fn, model](benchmark::State& s) { fn(s, model); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
  }
}

}  // namespace plumbago::bench
