// Texture generation (Lee et al. 2006, §4.2, §5.1, §5.5; Nienhaus & Döllner 2004, §3.2) at the default sizes: each
// generator's time.
#include <benchmark/benchmark.h>

#include "common/core/params.hpp"
#include "common/pencil/distortion.hpp"
#include "common/pencil/paper.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/util/noise.hpp"

namespace plumbago::bench {
namespace {

void BM_PencilLayers(benchmark::State& state) {
  auto p = ParamSet{}.get<PencilTexturesParams>();
  for (auto _ : state) benchmark::DoNotOptimize(pencil_layers(p, 1));
  state.counters["layers"] = p.layers;
  state.counters["size"] = p.size;
}
BENCHMARK(BM_PencilLayers)->Unit(benchmark::kMillisecond);

void BM_Paper(benchmark::State& state) {
  auto p = ParamSet{}.get<PaperParams>();
  for (auto _ : state) benchmark::DoNotOptimize(make_paper(p, 1));
  state.counters["size"] = p.size;
}
BENCHMARK(BM_Paper)->Unit(benchmark::kMillisecond);

void BM_DistortionGrids(benchmark::State& state) {
  auto p = ParamSet{}.get<ContourParams>();
  for (auto _ : state) benchmark::DoNotOptimize(distortion_grids(p, 800, 800, 1));
  state.counters["copies"] = p.copies;
}
BENCHMARK(BM_DistortionGrids)->Unit(benchmark::kMillisecond);

void BM_SketchyNoise(benchmark::State& state) {
  auto p = ParamSet{}.get<NoiseTextureParams>();
  for (auto _ : state) benchmark::DoNotOptimize(perlin_noise_texture(p, 1));
  state.counters["size"] = p.size;
}
BENCHMARK(BM_SketchyNoise)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace plumbago::bench
