// Silhouette chains (Kalnins et al. 2002, §4.5): the GPU's pointer jumping against the reference's
// walk, fed the same segments, and the reference's chains against the silhouettes that the
// stroke frame draws (common/strokes/strokes.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "common/mesh/procedural.hpp"
#include "common/strokes/silhouette_chains.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// The chains of a table: (length, closed) of each, in the order of their start records.
std::vector<std::pair<int, bool>> chains_by_start(const Image& table) {
  std::map<int, std::pair<int, bool>> by_start;
  for (size_t i = 0; i < table.pixels(); ++i) {
    const float* row = &table.data[i * 4];
    if (row[0] == 0) continue;
    EXPECT_LT(row[1], row[2]) << "record " << i << ": rank within the length";
    by_start[int(row[0])] = {int(row[2]), row[3] != 0};
  }
  std::vector<std::pair<int, bool>> out;
  for (const auto& [start, chain] : by_start) out.push_back(chain);
  return out;
}

// The same, sorted.
std::vector<std::pair<int, bool>> chains_of(const Image& table) {
  std::vector<std::pair<int, bool>> out = chains_by_start(table);
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

// More members than 65535 groups of 64 reach (GL's least maximum per dimension, which some
// drivers keep): the dispatch over them all goes 65535 x 2 groups, and a round of the loop
// search (shaders/strokes/silhouette_chains.comp STEP_LOOPS, self-loops here) reaches every
// member, the last of the second row too. No mesh of the suite has 4.2 million silhouette
// segments; this runs the pass's own steps on buffers made for them.
TEST_F(SilhouetteChains, MembersBeyondOneDispatchRowAreAllReached) {
  const uint32_t count = 64u * 65535u + 1000u;
  std::vector<uint32_t> members(count);
  std::vector<glm::uvec4> jump(2 * size_t(count));  // the two halves: round 0 reads the first
  for (uint32_t m = 0; m < count; ++m) members[m] = m, jump[m] = glm::uvec4(m, m, 0, 0);
  std::vector<uint32_t> args(4 + 2 * 32 * 4, 0);  // Count: count, all_x, all_y, all_z, round_groups, rank_groups
  args[0] = count;
  gpu::Buffer member_buffer = gpu::make_buffer(members.data(), count * sizeof(uint32_t));
  gpu::Buffer halves = gpu::make_buffer(jump.data(), jump.size() * sizeof(glm::uvec4));
  gpu::Buffer count_buffer = gpu::make_buffer(args.data(), args.size() * sizeof(uint32_t));
  for (auto [binding, buffer] : {std::pair{2, &member_buffer}, {3, &count_buffer}, {4, &halves}})
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer->id());
  gpu::Program step_args =
      gpu::Program::compute("strokes/silhouette_chains.comp", gpu::table_prelude() + "#define STEP_ARGS\n");
  gpu::Program loops =
      gpu::Program::compute("strokes/silhouette_chains.comp", gpu::table_prelude() + "#define STEP_LOOPS\n");
  glUseProgram(step_args.id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  gpu::read_buffer(count_buffer, args.data(), args.size() * sizeof(uint32_t));
  EXPECT_EQ((std::vector<uint32_t>(args.begin() + 1, args.begin() + 8)),
            (std::vector<uint32_t>{65535, 2, 1, 65535, 2, 1, 0}));  // all, then round 0's
  glProgramUniform1ui(loops.id(), loops.uniform("round_index"), 0);
  glProgramUniform1ui(loops.id(), loops.uniform("records"), count);
  glUseProgram(loops.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, count_buffer.id());
  glDispatchComputeIndirect(4 * sizeof(uint32_t));  // round_groups[0]
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gpu::read_buffer(halves, jump.data(), jump.size() * sizeof(glm::uvec4));
  uint32_t reached = 0;
  for (uint32_t m = 0; m < count; ++m) reached += jump[count + m] == glm::uvec4(m, m, 0, 0);
  EXPECT_EQ(reached, count);
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

// The silhouettes the stroke frame draws (common/strokes/strokes.hpp, back-facing ones kept):
// (segments, closed) of each, in key order.
std::vector<std::pair<int, bool>> window_silhouettes(Scene s) {
  s.params.set("strokes.keep_back_facing", 1.0);
  std::vector<std::pair<int, bool>> out;
  for (const WindowPath& p : window_lines(s, s.params.get<StrokesParams>()).paths)
    if (p.kind == LineKind::Silhouette) out.push_back({int(p.window.size()) - (p.closed ? 0 : 1), p.closed});
  return out;
}

// The table's chains are those silhouettes: as many, as long (in faces), as often closed and in
// the same order, that of their start records. The torus seen through its own near plane is
// cut there: it drops segments, and what is left chains the same way.
TEST_F(SilhouetteChains, ReferenceChainsAreTheWindowSilhouettesInStartOrder) {
  Scene cut = testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(1.65f, 0.3f, 0.2f));
  cut.camera.near = 0.7f;  // the near tube's silhouette lies about 0.58 from the eye
  std::vector<std::pair<std::string, Scene>> scenes = {
      {"torus", testing::drawn_with_strokes(testing::builtin_at("torus", 320, 240))},
      {"sphere", testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240))},
      {"fine torus", testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f))},
      {"torus cut by the near plane", cut}};
  for (auto& [name, s] : scenes) {
    s.params.set("strokes.keep_back_facing", 1.0);
    EXPECT_EQ(chains_by_start(chain_parity(s, name).first), window_silhouettes(s)) << name;
  }
  auto segments = [](const std::vector<std::pair<int, bool>>& chains) {
    int n = 0;
    for (auto [length, closed] : chains) n += length;
    return n;
  };
  Scene whole = cut;
  whole.camera.near = 1e-3f;
  EXPECT_LT(segments(window_silhouettes(cut)), segments(window_silhouettes(whole)) - 10);
}

}  // namespace
}  // namespace plumbago
