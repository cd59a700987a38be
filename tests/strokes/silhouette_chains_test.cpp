// Silhouette chains (Kalnins et al. 2002, §4.5): the GPU's pointer jumping against the reference's
// walk, fed the same segments, and the reference's chains against the paths that
// common/strokes/feature_lines.hpp traces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "common/mesh/procedural.hpp"
#include "common/strokes/silhouette_chains.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// The chains of a table: (length, closed) of each, sorted.
std::vector<std::pair<int, bool>> chains_of(const Image& table) {
  std::map<int, std::pair<int, bool>> by_start;
  for (size_t i = 0; i < table.pixels(); ++i) {
    const float* row = &table.data[i * 4];
    if (row[0] == 0) continue;
    EXPECT_LT(row[1], row[2]) << "record " << i << ": rank within the length";
    by_start[int(row[0])] = {int(row[2]), row[3] != 0};
  }
  std::vector<std::pair<int, bool>> out;
  for (const auto& [start, chain] : by_start) out.push_back(chain);
  std::sort(out.begin(), out.end());
  return out;
}

// Per chain (by start), its arcs rows in rank order: s rises from 0 by each segment's length.
void expect_arcs_add_up(const Image& chains, const Image& arcs, const std::string& label) {
  std::map<int, std::vector<std::pair<int, size_t>>> by_start;
  for (size_t i = 0; i < chains.pixels(); ++i)
    if (chains.data[i * 4] != 0) by_start[int(chains.data[i * 4])].push_back({int(chains.data[i * 4 + 1]), i});
  for (auto& [start, members] : by_start) {
    std::sort(members.begin(), members.end());
    EXPECT_EQ(arcs.data[members.front().second * 2], 0.0f) << label << ": the start's s";
    for (size_t k = 1; k < members.size(); ++k)
      EXPECT_GT(arcs.data[members[k].second * 2], arcs.data[members[k - 1].second * 2]) << label << " start " << start;
    EXPECT_GE(arcs.data[members.back().second * 2 + 1], arcs.data[members.back().second * 2]) << label;
  }
}

// The parity of both outputs, printed; the reference's chains and arcs.
std::pair<Image, Image> chain_parity(const Scene& scene, const std::string& label) {
  std::vector<StageParity> results = run_parity(scene, {"silhouette_chains"});
  EXPECT_EQ(testing::names_of(results), (std::vector<std::string>{kChains.name, kChainArcs.name})) << label;
  if (results.size() != 2) return {};
  const StageParity& r = results[0];
  const StageParity& arcs = results[1];
  std::printf("[chains %s] %s  bound allows %zu  [%s]\n", label.c_str(), format_diff(arcs.name, arcs.diff).c_str(),
              arcs.bounded, arcs.note.c_str());
  EXPECT_TRUE(arcs.pass) << label << ": " << arcs.note;
  expect_arcs_add_up(r.gpu, arcs.gpu, label + " (GPU)");
  std::vector<std::pair<int, bool>> chains = chains_of(r.reference);
  size_t closed = size_t(std::count_if(chains.begin(), chains.end(), [](auto c) { return c.second; }));
  std::printf("[chains %s] %s: %zu chains, %zu closed  [%s]\n", label.c_str(), format_diff(r.name, r.diff).c_str(),
              chains.size(), closed, r.note.c_str());
  EXPECT_TRUE(r.pass) << label << ": " << r.note;
  EXPECT_EQ(chains_of(r.gpu), chains) << label;
  return {r.reference, arcs.reference};
}

class SilhouetteChains : public testing::GlTest {};

TEST_F(SilhouetteChains, GpuRanksTheSameChainsAsTheWalk) {
  for (const char* name : {"torus", "sphere", "cad"})
    chain_parity(testing::drawn_with_strokes(testing::builtin_at(name, 320, 240)), name);
  chain_parity(testing::drawn_with_strokes(testing::square_and_torus("continuous")), "two objects");
}

// A finer torus than the built-in one, seen from where its silhouette has several loops and
// open paths cut by the facing: many members and rounds.
TEST_F(SilhouetteChains, FineTorusFromAbove) {
  Image table = chain_parity(testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f)),
                             "fine torus")
                    .first;
  EXPECT_GE(chains_of(table).size(), 2u);
}

// A sphere seen along the line through its center: one loop, as long as the circle it
// projects to, of radius (H / 2) tan(asin(1 / D)) / tan(fov / 2) px; the inscribed polygon
// is shorter by its chord error (under 0.1% for this sphere's edge angles).
TEST_F(SilhouetteChains, SphereLoopIsAsLongAsItsCircle) {
  const double D = 4;
  Scene s = testing::one_stroke_object(make_procedural("sphere", 1.0f), glm::vec3(0, 0, float(D)), 400, 400);
  auto [table, arcs] = chain_parity(s, "sphere on axis");
  ASSERT_EQ(chains_of(table), (std::vector<std::pair<int, bool>>{{chains_of(table)[0].first, true}}));
  double radius = 200 * std::tan(std::asin(1 / D)) / std::tan(double(s.camera.fov_deg) * std::numbers::pi / 360);
  double length = 0;
  for (size_t i = 0; i < arcs.pixels(); ++i) length = std::max(length, double(arcs.data[i * 2 + 1]));
  std::printf("sphere loop: %.2f px, circle %.2f px\n", length, 2 * std::numbers::pi * radius);
  EXPECT_NEAR(length / (2 * std::numbers::pi * radius), 1.0, 2e-3);
}

// The table's chains are the silhouettes common/strokes/feature_lines.hpp traces (back-facing
// ones kept): as many, as long (in faces) and as often closed.
TEST_F(SilhouetteChains, ReferenceChainsAreTheTracedSilhouettes) {
  std::vector<std::pair<std::string, Scene>> scenes = {
      {"torus", testing::drawn_with_strokes(testing::builtin_at("torus", 320, 240))},
      {"sphere", testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240))},
      {"fine torus", testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f))}};
  for (const auto& [name, s] : scenes) {
    Image table = chain_parity(s, name).first;
    FeatureLineOptions keep;
    keep.keep_back_facing = true;
    FeatureLines lines =
        feature_lines(*s.objects[0].mesh, glm::dmat4(s.objects[0].transform), glm::dvec3(s.camera.eye), keep);
    std::vector<std::pair<int, bool>> traced;
    for (const FeaturePath& p : lines.silhouettes)
      traced.push_back({int(p.points.size()) - (p.closed ? 0 : 1), p.closed});
    std::sort(traced.begin(), traced.end());
    EXPECT_EQ(chains_of(table), traced) << name;
  }
}

}  // namespace
}  // namespace plumbago
