// Silhouette paths (Kalnins et al. 2002, §4.5): the GPU's prefix-sum layout against the
// reference's loop, fed the same chains; and the GPU frame's own silhouettes, from its own
// segments, chains and points, against the paths the reference draws in double.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "common/mesh/procedural.hpp"
#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "common/strokes/decal.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "common/strokes/strokes.hpp"
#include "common/strokes/visibility.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/strokes/window_paths.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kPathResults = {kSilhouettePaths.name, kSilhouettePoints.name,
                                               kSilhouetteCrossings.name};

// Two objects, the second turned, scaled and moved (the GPU's points go through each one's
// own transform and eye), with g = n·(eye - x) unnormalized.
Scene turned_unnormalized() {
  Scene s = testing::drawn_with_strokes(testing::square_and_torus("continuous"));
  glm::mat4& m = s.objects.back().transform;
  m = glm::rotate(glm::translate(m, glm::vec3(0.2f, -0.1f, 0.3f)), 0.7f, glm::vec3(0.3f, 1.0f, 0.2f));
  m = glm::scale(m, glm::vec3(1.3f, 0.8f, 1.1f));
  s.params.set("strokes.silhouette_normalized", 0.0);
  return s;
}

std::vector<std::pair<std::string, Scene>> scenes() {
  return {{"torus", testing::drawn_with_strokes(testing::builtin_at("torus", 320, 240))},
          {"sphere", testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240))},
          {"cad", testing::drawn_with_strokes(testing::builtin_at("cad", 320, 240))},
          {"two objects", testing::drawn_with_strokes(testing::square_and_torus("continuous"))},
          {"fine torus", testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f))},
          {"turned, g unnormalized", turned_unnormalized()}};
}

// The tables' counts agree with their rows: each path's points follow the one before's, its
// arc length rises from 0 along them, and exactly the counted points have a crossing.
void expect_consistent(const Image& paths, const Image& points, const Image& crossings, const std::string& label) {
  const auto path_count = size_t(paths.data[0]), point_count = size_t(paths.data[1]);
  size_t next = 0;
  for (size_t p = 1; p <= path_count; ++p) {
    const float* row = &paths.data[4 * p];
    ASSERT_EQ(size_t(row[1]), next) << label << " path " << p - 1;
    EXPECT_GE(row[2], 2.0f) << label;
    EXPECT_EQ(points.data[3 * next + 2], 0.0f) << label << ": s at a path's start";
    for (size_t q = next + 1; q < next + size_t(row[2]); ++q) EXPECT_GT(points.data[3 * q + 2], points.data[3 * q - 1]);
    next += size_t(row[2]);
  }
  EXPECT_EQ(next, point_count) << label;
  EXPECT_GT(path_count, 0u) << label;
  for (size_t q = 0; q < crossings.pixels(); ++q)
    EXPECT_EQ(crossings.data[2 * q] != 0, q < point_count) << label << " row " << q;
}

class SilhouettePaths : public testing::GlTest {};

TEST_F(SilhouettePaths, GpuLaysOutTheChainsAsTheReferenceDoes) {
  for (auto& [name, s] : scenes())
    for (bool keep : {false, true}) {
      s.params.set("strokes.keep_back_facing", keep ? 1.0 : 0.0);
      std::string label = name + (keep ? ", back-facing kept" : "");
      std::vector<StageParity> r = testing::table_parity(s, "silhouette_paths", kPathResults, label);
      ASSERT_EQ(r.size(), 3u);
      expect_consistent(r[0].gpu, r[1].gpu, r[2].gpu, label + " (GPU)");
      expect_consistent(r[0].reference, r[1].reference, r[2].reference, label + " (reference)");
      std::printf("[paths %s] %g paths, %g points\n", label.c_str(), r[0].gpu.data[0], r[0].gpu.data[1]);
    }
}

std::vector<const WindowPath*> silhouettes_of(const WindowLines& lines) {
  std::vector<const WindowPath*> out;
  for (const WindowPath& w : lines.paths)
    if (w.kind == LineKind::Silhouette) out.push_back(&w);
  return out;
}

// Both backends place a point in double from the same float corners and double normals (the
// GPU in shaders/strokes/silhouette_points.comp): they may differ by the rounding of a few
// double operations (a fused multiply-add, a division, a square root), each within 2^-52
// of its value: some 1e-13 of the window's size (measured: at most 1.2e-13 px at 320 x 240).
constexpr double kDoublePointPx = 1e-9, kDoubleRelative = 1e-12;

// The silhouettes of the GPU frame, from its own segments, chains and points placed in
// double (gpu/strokes/silhouette_points.hpp), against those the reference chains in double:
// the same paths, keys and points, wherever the derived bound of the segments names no face
// whose sign may flip (then the chains may differ there, and only their counts are printed).
// The tables' float points lie within a segment end's bound of the reference's.
TEST_F(SilhouettePaths, GpuFrameChainsTheSilhouettesTheReferenceDraws) {
  for (auto& [name, s] : scenes()) {
    std::vector<StageParity> segments = run_parity(s, {"silhouette_segments"});
    ASSERT_EQ(segments.size(), 3u);
    const size_t ambiguous = segments[1].bounded;  // the facing: faces whose signs may flip
    Frame frame = gpu::Renderer(s).render(FrameOptions{true});
    const Image &paths = frame.buffers.at(kSilhouettePaths.name), &points = frame.buffers.at(kSilhouettePoints.name),
                &crossings = frame.buffers.at(kSilhouetteCrossings.name);
    expect_consistent(paths, points, crossings, name + " (GPU frame)");
    ASSERT_TRUE(frame.lines) << name;
    const StrokesParams p = s.params.get<StrokesParams>();
    WindowLines reference = window_lines(s, p, LineObjects::Strokes);
    std::vector<const WindowPath*> gpu = silhouettes_of(*frame.lines), drawn = silhouettes_of(reference);
    std::printf("[GPU frame %s] %zu silhouettes (reference %zu), %zu faces whose sign may flip\n", name.c_str(),
                gpu.size(), drawn.size(), ambiguous);
    if (ambiguous > 0) continue;
    ASSERT_EQ(gpu.size(), drawn.size()) << name;
    double table = 0, window = 0, depth = 0, surface = 0;
    for (size_t i = 0, q = 0; i < gpu.size(); ++i) {
      const WindowPath &g = *gpu[i], &w = *drawn[i];
      EXPECT_EQ(g.key, w.key) << name << " path " << i;
      EXPECT_EQ(g.closed, w.closed) << name << " path " << i;
      ASSERT_EQ(g.window.size(), w.window.size()) << name << " path " << i;
      for (size_t k = 0; k < w.window.size(); ++k, ++q) {
        EXPECT_EQ(g.surface[k].face, w.surface[k].face) << name << " path " << i << " point " << k;
        table = std::max(table, glm::distance(glm::dvec2(points.data[3 * q], points.data[3 * q + 1]), w.window[k]));
        window = std::max(window, glm::distance(g.window[k], w.window[k]));
        depth = std::max(depth, std::abs(g.depth[k] - w.depth[k]) / w.depth[k]);
        surface = std::max(surface, glm::distance(g.surface[k].position, w.surface[k].position) /
                                        std::max(1.0, glm::length(w.surface[k].position)));
      }
    }
    std::printf(
        "[GPU frame %s] points from the reference's: table (float) %.3g px; in double: window %.3g px, "
        "depth %.3g relative, surface %.3g relative\n",
        name.c_str(), table, window, depth, surface);
    EXPECT_LT(table, kSegmentEndPx) << name;
    EXPECT_LT(window, kDoublePointPx) << name;
    EXPECT_LT(depth, kDoubleRelative) << name;
    EXPECT_LT(surface, kDoubleRelative) << name;
  }
}

// A stroke torus seen from within its tube's reach, nearer to it than the near plane: its
// silhouettes are cut there, some into pieces of which a path keeps its first.
Scene torus_cut_by_the_near_plane() {
  Scene s = testing::one_stroke_object(make_procedural("torus"), glm::vec3(1.65f, 0.0f, 0.0f));
  s.camera.near = 0.3f;
  return s;
}

// The CAD part seen from near its corner, nearer to it than the near plane: its creases are
// cut there, some into two pieces or more.
Scene cad_cut_by_the_near_plane() {
  Scene s = testing::one_stroke_object(make_procedural("cad"), glm::vec3(0.9f, 0.7f, 0.8f));
  s.camera.near = 0.9f;
  return s;
}

// How many of the crease and border points of `s`'s first object lie nearer than its near
// plane, and how many paths they make.
std::pair<size_t, size_t> crease_points_behind(const Scene& s) {
  auto meshes = line_meshes(s, s.params.get<StrokesParams>(), LineObjects::Strokes);
  const FeatureLines& lines = line_mesh(*meshes, 0)->creases_and_borders();
  const glm::vec3 forward = glm::normalize(s.camera.target - s.camera.eye);
  size_t behind = 0, paths = 0;
  for (const auto* kind : {&lines.creases, &lines.borders})
    for (const FeaturePath& p : *kind) {
      ++paths;
      for (const SurfacePoint& q : p.points)
        behind += glm::dot(glm::vec3(q.position) - s.camera.eye, forward) < s.camera.near;
    }
  return {behind, paths};
}

// The rows of the table `table` holds on the GPU, as its header counts them: its paths, and
// its points up to the last a path names; with the header's dispatches, which must cover its
// entries and paths.
gpu::PathTable read_rows(const gpu::UploadedPaths& table) {
  gpu::TableHeader h;
  gpu::read_buffer(table.paths, &h, sizeof h);
  gpu::PathTable rows(WindowLines{});
  rows.paths.resize(h.paths);
  gpu::read_buffer(table.paths, rows.paths.data(), rows.paths.size() * sizeof(gpu::PathRow), sizeof h);
  size_t points = 0;
  for (const gpu::PathRow& p : rows.paths) points = std::max<size_t>(points, p.first_point + p.points);
  rows.points.resize(points);
  gpu::read_buffer(table.points, rows.points.data(), points * sizeof(gpu::PointRow));
  rows.entries = h.entries, rows.silhouette_entry = h.silhouette_entry;
  EXPECT_LE(h.paths, table.path_bound);
  EXPECT_LE(h.entries, table.entry_bound);
  auto expect_covers = [](const uint32_t groups[3], uint32_t count) {  // rows of 64, at most one group row spare
    const size_t rows = size_t(groups[0]) * groups[1] * 64;
    EXPECT_GE(rows, count);
    EXPECT_LT(rows, size_t(count) + size_t(groups[0]) * 64 + 1);
    EXPECT_LE(groups[0], 65535u);
    EXPECT_EQ(groups[2], 1u);
  };
  expect_covers(h.over_entries, h.entries);
  expect_covers(h.over_paths, h.paths);
  return rows;
}

// The bounds the GPU summed for its paths (gpu/strokes/row_counts.hpp), by which the CPU sizes
// the visibility and stroke buffers, against the same bounds of the CPU's paths
// (first_round_bound, gpu::run_bound), per line style: at least those, and more by less than
// 1 a path (the GPU rounds each path's up to an integer).
void expect_gpu_bounds(const WindowLines& lines, const gpu::UploadedPaths& table, double step,
                       const std::string& name) {
  double first_round = 0;
  std::map<uint32_t, gpu::RunBound> cpu, gpu;  // per line style (gpu::PathTable::style_of)
  std::map<uint32_t, double> paths;
  for (const WindowPath& p : lines.paths) {
    const uint32_t style = gpu::PathTable::style_of(p);
    const double s = first_round_bound(p, step, lines.width, lines.height);
    const gpu::RunBound b = gpu::run_bound(p, s, lines.width, lines.height);
    first_round += s, cpu[style].runs += b.runs, cpu[style].length += b.length, cpu[style].points += b.points;
    paths[style] += 1;
  }
  EXPECT_GE(table.gpu_first_round, first_round - 1e-6) << name;
  EXPECT_LT(table.gpu_first_round, first_round + double(lines.paths.size())) << name;
  for (const gpu::RunBound& b : table.gpu) gpu[b.style] = b;
  EXPECT_EQ(gpu.size(), cpu.size()) << name;
  for (const auto& [style, c] : cpu) {
    const std::string at = name + " style " + std::to_string(style);
    const gpu::RunBound& g = gpu[style];
    EXPECT_EQ(g.runs, c.runs) << at;
    EXPECT_EQ(g.points, c.points) << at;
    EXPECT_GE(g.length, c.length - 1e-6) << at;
    EXPECT_LT(g.length, c.length + paths[style] + 1e-6) << at;
  }
}

// The GPU frame writes the window paths of its creases, borders, silhouettes, decals and
// hatches itself (gpu/strokes/crease_rows.hpp, silhouette_rows.hpp, decal_rows.hpp, the last
// with a mobile hatch's copies moved in its group's chart; the crease and decal rows' pieces
// and rows by piece_rows.hpp; the CPU reads back only their counts and bounds): its path
// table's rows against those the CPU makes of the same points (common/strokes/strokes.cpp
// window_lines, which a frame that keeps its lines whole runs too): the same paths, counts, keys, kinds, weights,
// entries, segment faces and pressures exactly; the silhouettes' window points and depths exactly (the same doubles),
// the others' within the rounding of a few double operations, as are arc lengths, lengths and world steps.
TEST_F(SilhouettePaths, GpuWritesTheWindowPathsTheCpuMakesOfItsPoints) {
  std::vector<std::pair<std::string, Scene>> all = scenes();
  all.emplace_back("torus cut by the near plane", torus_cut_by_the_near_plane());
  all.emplace_back("CAD part cut by the near plane", cad_cut_by_the_near_plane());
  all.emplace_back("fine torus, back-facing kept", all[4].second);
  all.back().second.params.set("strokes.keep_back_facing", 1.0);
  all.emplace_back("sphere with hatches", load_scene(PLUMBAGO_SOURCE_DIR "/scenes/hatching_lod.json"));
  all.emplace_back("teapot with decals", load_scene(PLUMBAGO_SOURCE_DIR "/scenes/teapot_decals.json"));
  all.emplace_back("snowman with mobile hatching", load_scene(PLUMBAGO_SOURCE_DIR "/scenes/snowman_mobile.json"));
  // Its orbit's last frame, the copies moved along their u-lines on the GPU; then the same with
  // the trees' cones stripped of their (u, v): the groups travel on LSCM patches.
  all.emplace_back("snowman, orbit's end", scene_at_frame(all.back().second, all.back().second.animation->frames - 1));
  all.emplace_back("snowman, orbit's end, patch charts", testing::cones_without_uvs(all.back().second));
  all.emplace_back("storefront", load_scene(PLUMBAGO_SOURCE_DIR "/scenes/storefront_strokes.json"));
  const auto [behind, crease_paths] = crease_points_behind(cad_cut_by_the_near_plane());
  std::printf("CAD part: %zu of its points on %zu crease and border paths nearer than its near plane\n", behind,
              crease_paths);
  ASSERT_GT(behind, 0u);
  for (auto& [name, s] : all) {
    gpu::Renderer renderer(s);
    Frame frame = renderer.render(FrameOptions{true});
    ASSERT_TRUE(frame.lines) << name;
    const gpu::UploadedPaths* table = renderer.frame().get(maybe(gpu::kPathTable));
    ASSERT_TRUE(table) << name;
    const gpu::PathTable cpu(*frame.lines), gpu_rows = read_rows(*table);
    ASSERT_EQ(gpu_rows.paths.size(), cpu.paths.size()) << name;
    EXPECT_EQ(gpu_rows.entries, cpu.entries) << name;
    EXPECT_EQ(gpu_rows.silhouette_entry, cpu.silhouette_entry) << name;
    double window = 0, depth = 0, arc = 0, step = 0;
    size_t made[4] = {0, 0, 0, 0}, cut = 0;  // creases, borders, silhouettes, decals and hatches
    for (size_t i = 0; i < cpu.paths.size(); ++i) {
      const gpu::PathRow &g = gpu_rows.paths[i], &c = cpu.paths[i];
      const std::string at = name + " path " + std::to_string(i);
      ASSERT_EQ(g.points, c.points) << at;
      EXPECT_EQ(g.first_entry, c.first_entry) << at;
      EXPECT_EQ(g.kind, c.kind) << at;
      EXPECT_EQ(g.key, c.key) << at;
      EXPECT_EQ(g.byte_window, c.byte_window) << at;
      EXPECT_EQ(g.style, c.style) << at;
      EXPECT_NEAR(g.length_px, c.length_px, kDoubleRelative * std::max(1.0, c.length_px)) << at;
      EXPECT_EQ(g.alpha_scale, c.alpha_scale) << at;
      EXPECT_EQ(g.width_scale, c.width_scale) << at;
      ++made[std::min<uint32_t>(c.style, 3)], cut += (c.kind & 16u) == 0;
      for (uint32_t k = 0; k < c.points; ++k) {
        const gpu::PointRow &gp = gpu_rows.points[g.first_point + k], &cp = cpu.points[c.first_point + k];
        EXPECT_EQ(gp.faces, cp.faces) << at << " point " << k;
        EXPECT_EQ(gp.pressure, cp.pressure) << at << " point " << k;
        if (c.style == 2) {
          EXPECT_EQ(gp.window, cp.window) << at << " point " << k;
        }
        window = std::max(window, glm::distance(gp.window, cp.window));
        depth = std::max(depth, std::abs(gp.depth - cp.depth) / cp.depth);
        arc = std::max(arc, std::abs(gp.s - cp.s) / std::max(1.0, c.length_px));
        step = std::max(step, std::abs(gp.world_step - cp.world_step) / std::max(1.0, cp.world_step));
      }
    }
    std::printf(
        "[GPU rows %s] %zu crease, %zu border, %zu silhouette, %zu decal and hatch paths (%zu open); window %.3g "
        "px, depth %.3g, arc lengths %.3g, world steps %.3g relative\n",
        name.c_str(), made[0], made[1], made[2], made[3], cut, window, depth, arc, step);
    if (has_decals(s)) {
      EXPECT_GT(made[3], 0u) << name;
    }
    EXPECT_GT(made[0] + made[1] + made[2], 0u) << name;
    EXPECT_LT(window, kDoublePointPx) << name;
    EXPECT_LT(depth, kDoubleRelative) << name;
    EXPECT_LT(arc, kDoubleRelative) << name;
    EXPECT_LT(step, kDoubleRelative) << name;
    expect_gpu_bounds(*frame.lines, *table, s.params.get<StrokesParams>().vis_step_px, name);
  }
}

// A backend's silhouette whose point double precision puts behind the near plane (its float
// chain kept the segment) keeps one piece, its first of two points or more, under its chain's
// key: no second path may carry the same key.
TEST(SilhouettePathsNearPlane, AChainCutInDoubleKeepsOnePieceUnderItsKey) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240));
  s.camera = Camera{};  // the eye at (0, 0, 5), near 0.1
  s.objects.resize(1);
  s.objects[0].transform = glm::mat4(1.0f);
  auto at = [](double x, double y, double z) { return SurfacePoint{0, glm::dvec3(1, 0, 0), glm::dvec3(x, y, z)}; };
  const uint32_t start = 7;
  std::vector<ChainPath> chain = {
      {0, start, {{at(1, 0, 0), at(0, 1, 0), at(0, 0, 4.95), at(-1, 0, 0), at(0, -1, 0)}, false, true}}};
  const StrokesParams p = s.params.get<StrokesParams>();
  WindowLines lines = window_lines(s, p, LineObjects::Strokes, nullptr, nullptr, &chain);
  std::vector<const WindowPath*> silhouettes = silhouettes_of(lines);
  ASSERT_EQ(silhouettes.size(), 1u);
  EXPECT_EQ(silhouettes[0]->key, lines.silhouette_base + start);
  EXPECT_EQ(silhouettes[0]->window.size(), 2u);
}

}  // namespace
}  // namespace plumbago
