// The exact clipping of the curvature ball (common/curvature/ball_geometry.hpp, Lee et al. 2006, §5.3; Alliez et al.
// 2003): what one face or side the sphere cuts costs. The ball's cost is mostly its cut band (docs/curvature.md:
// 217 cut faces per ball on bunny-1M), so this is the number the 5 s per million target
// hinges on. Faces with sides of about 1 (some irregular), their centroids within 1 of a
// sphere of radius 5, as in a ball five edges wide.
#include <benchmark/benchmark.h>

#include <numbers>
#include <vector>

#include "common/curvature/ball_geometry.hpp"
#include "common/util/random.hpp"

namespace plumbago::bench {
namespace {

constexpr double kRadius = 5;

struct CutFace {
  glm::dvec3 p[3], N;
  double N_length;
};

std::vector<CutFace> cut_faces(size_t n) {
  Rng rng(1, "ball-geometry-bench");
  auto unit = [&] {
    glm::dvec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    return glm::length(v) > 1e-3 ? glm::normalize(v) : glm::dvec3(1, 0, 0);
  };
  std::vector<CutFace> faces;
  while (faces.size() < n) {
    const glm::dvec3 centroid = (kRadius + rng.uniform(-1, 1)) * unit(), x = unit(), across = glm::cross(unit(), x);
    if (glm::length(across) < 1e-3) continue;
    const glm::dvec3 y = glm::normalize(across);  // x and y span the face's plane
    CutFace f;
    for (int k = 0; k < 3; ++k) {
      const double angle = 2 * std::numbers::pi / 3 * k + rng.uniform(-0.4, 0.4);
      f.p[k] = centroid + 0.6 * (std::cos(angle) * x + std::sin(angle) * y);
    }
    int inside = 0;
    for (const auto& p : f.p) inside += glm::dot(p, p) <= kRadius * kRadius;
    if (inside == 0 || inside == 3) continue;  // cut faces only: a corner on each side
    f.N = glm::cross(f.p[1] - f.p[0], f.p[2] - f.p[0]);
    f.N_length = glm::length(f.N);
    faces.push_back(f);
  }
  return faces;
}

void BM_TriangleAreaInBall_CutFace(benchmark::State& state) {
  const std::vector<CutFace> faces = cut_faces(4096);
  size_t i = 0;
  for (auto _ : state) {
    const CutFace& f = faces[i++ % faces.size()];
    benchmark::DoNotOptimize(triangle_area_in_ball(f.p[0], f.p[1], f.p[2], glm::dvec3(0), kRadius, f.N, f.N_length));
  }
}
BENCHMARK(BM_TriangleAreaInBall_CutFace);

void BM_SegmentFractionInBall_CutSide(benchmark::State& state) {
  const std::vector<CutFace> faces = cut_faces(4096);
  size_t i = 0;
  for (auto _ : state) {
    const CutFace& f = faces[(i / 3) % faces.size()];
    const int k = int(i++ % 3);
    benchmark::DoNotOptimize(segment_fraction_in_ball(f.p[k], f.p[(k + 1) % 3], glm::dvec3(0), kRadius));
  }
}
BENCHMARK(BM_SegmentFractionInBall_CutSide);

}  // namespace
}  // namespace plumbago::bench
