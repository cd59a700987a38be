// Principal curvature (Lee et al. 2006, §5.3; Alliez et al. 2003), uncached, on the shared models and on a bunny
// subdivided 1-to-4 until it has at least a million vertices. Reported per run and as
// seconds per million vertices, next to the targets on 2 cores: 1-ring <= 0.5 s,
// default ball <= 5 s per million vertices. `topology_ms` is the share spent building
// the adjacency (in parallel; OpenMesh only for non-manifold input); `uniform_faces_per_ball`
// is how many faces the ball would hold if every face had the mean area (the cost of a
// ball grows with its faces; a mesh with dense details, like the ogre, holds many more
// where it is dense).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>

#include "common/core/frame.hpp"
#include "common/core/params.hpp"
#include "common/curvature/curvature.hpp"
#include "common/mesh/mesh_topology.hpp"

namespace plumbago::bench {
namespace {

// One 1-to-4 split: a vertex at each edge midpoint, four triangles per triangle.
Mesh subdivide(const Mesh& in) {
  Mesh out;
  out.name = in.name + " (subdivided)";
  out.positions = in.positions;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
  auto middle = [&](uint32_t a, uint32_t b) {
    auto [it, added] = midpoint.try_emplace({std::min(a, b), std::max(a, b)}, uint32_t(out.positions.size()));
    if (added) out.positions.push_back(0.5f * (in.positions[a] + in.positions[b]));
    return it->second;
  };
  for (const auto& t : in.triangles) {
    uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  compute_normals(out);
  return out;
}

// Loaded once per process; nullptr when the model is not there.
std::shared_ptr<const Mesh> bench_mesh(const std::string& name) {
  static std::map<std::string, std::shared_ptr<const Mesh>> loaded;
  if (auto it = loaded.find(name); it != loaded.end()) return it->second;
  std::shared_ptr<const Mesh> mesh;
  if (name == "bunny-1M") {
    if (auto bunny = bench_mesh("stanford-bunny.obj")) {
      Mesh m = *bunny;
      while (m.positions.size() < 1000000) m = subdivide(m);
      mesh = std::make_shared<const Mesh>(std::move(m));
    }
  } else if (std::filesystem::exists(std::string(PLUMBAGO_MODELS_DIR) + "/" + name)) {
    mesh = std::make_shared<const Mesh>(load_mesh(std::string(PLUMBAGO_MODELS_DIR) + "/" + name));
  }
  return loaded[name] = mesh;
}

double mean_face_area(const Mesh& m) {
  double sum = 0;
  for (const auto& t : m.triangles)
    sum += 0.5 * glm::length(glm::cross(glm::dvec3(m.positions[t[1]] - m.positions[t[0]]),
                                        glm::dvec3(m.positions[t[2]] - m.positions[t[0]])));
  return sum / double(m.triangles.size());
}

void curvature(benchmark::State& state, const std::string& model, const std::vector<std::string>& assignments) {
  auto mesh = bench_mesh(model);
  if (!mesh) {
    state.SkipWithError(("../shared/models/" + model + " is not here").c_str());
    return;
  }
  ParamSet set;
  for (const auto& a : assignments) set.set_assignment(a);
  CurvatureParams p = set.get<CurvatureParams>();
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(estimate_curvature(*mesh, p));
    state.SetIterationTime(w.ms() * 1e-3);
  }
  Stopwatch topology;
  benchmark::DoNotOptimize(build_topology(*mesh));
  double vertices = double(mesh->positions.size());
  state.counters["vertices"] = vertices;
  state.counters["topology_ms"] = topology.ms();
  state.counters["vertices_per_s"] = benchmark::Counter(vertices, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["s_per_1M_vertices"] =
      benchmark::Counter(vertices / 1e6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  double r = p.radius * mesh->bbox_diagonal();
  state.counters["uniform_faces_per_ball"] = r > 0 ? std::numbers::pi * r * r / mean_face_area(*mesh) : 0.0;
}

const bool registered = [] {
  const std::vector<std::pair<std::string, std::vector<std::string>>> variants = {
      {"tensor_1ring", {"curvature.method=tensor", "curvature.radius=0"}},
      {"tensor_default", {"curvature.method=tensor"}},
      {"auto_default", {}},  // the default: the jet where faces fold, else the tensor
      {"jet_default", {"curvature.method=jet"}},
      {"tensor_approximate_ball", {"curvature.method=tensor", "curvature.ball_clip=approximate"}},
      {"jet_cgal", {"curvature.method=jet", "curvature.jet_solver=cgal"}}};
  for (const std::string model : {"fandisk.obj", "stanford-bunny.obj", "ogre.obj", "bunny-1M"})
    for (const auto& [name, assignments] : variants) {
      std::string stem = std::filesystem::path(model).stem().string();
      auto* b =
          benchmark::RegisterBenchmark(("BM_Curvature/" + stem + "/" + name).c_str(),
                                       [model, assignments](benchmark::State& s) { curvature(s, model, assignments); });
      b->Unit(benchmark::kMillisecond)->UseManualTime();
      if (model == "bunny-1M") b->Iterations(1);
    }
  return true;
}();

}  // namespace
}  // namespace plumbago::bench
