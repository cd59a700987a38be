// Silhouette paths (Kalnins et al. 2002, §4.5): the GPU's prefix-sum layout against the
// reference's loop, fed the same chains; and the GPU frame's own silhouettes, from its own
// segments and chains, against the paths the reference draws in double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/mesh/procedural.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kPathResults = {kSilhouettePaths.name, kSilhouettePoints.name,
                                               kSilhouetteCrossings.name};

std::vector<std::pair<std::string, Scene>> scenes() {
  return {{"torus", testing::drawn_with_strokes(testing::builtin_at("torus", 320, 240))},
          {"sphere", testing::drawn_with_strokes(testing::builtin_at("sphere", 320, 240))},
          {"cad", testing::drawn_with_strokes(testing::builtin_at("cad", 320, 240))},
          {"two objects", testing::drawn_with_strokes(testing::square_and_torus("continuous"))},
          {"fine torus", testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f))}};
}

std::vector<float> values(const Image& table) { return table.data; }

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

// The silhouettes of the GPU frame, read from its own tables (common/strokes/silhouette_paths.hpp
// chain_paths), against those the reference chains in double: the same paths, keys and points,
// wherever the derived bound of the segments names no face whose sign may flip (then the
// chains may differ there, and only their counts are printed).
TEST_F(SilhouettePaths, GpuFrameChainsTheSilhouettesTheReferenceDraws) {
  for (auto& [name, s] : scenes()) {
    std::vector<StageParity> segments = run_parity(s, {"silhouette_segments"});
    ASSERT_EQ(segments.size(), 3u);
    const size_t ambiguous = segments[1].bounded;  // the facing: faces whose signs may flip
    Frame frame = gpu::Renderer(s).render(FrameOptions{true});
    const Image &paths = frame.buffers.at(kSilhouettePaths.name), &points = frame.buffers.at(kSilhouettePoints.name),
                &crossings = frame.buffers.at(kSilhouetteCrossings.name);
    expect_consistent(paths, points, crossings, name + " (GPU frame)");
    const StrokesParams p = s.params.get<StrokesParams>();
    std::shared_ptr<const LineMeshes> meshes = line_meshes(s, p, LineObjects::Strokes);
    std::vector<ChainPath> gpu = chain_paths(s, *meshes, values(paths), values(crossings), p.silhouette_normalized);
    WindowLines reference = window_lines(s, p, LineObjects::Strokes, meshes.get());
    std::vector<const WindowPath*> drawn;
    for (const WindowPath& w : reference.paths)
      if (w.kind == LineKind::Silhouette) drawn.push_back(&w);
    std::printf("[GPU frame %s] %zu silhouettes (reference %zu), %zu faces whose sign may flip\n", name.c_str(),
                gpu.size(), drawn.size(), ambiguous);
    if (ambiguous > 0) continue;
    ASSERT_EQ(gpu.size(), drawn.size()) << name;
    double worst = 0;
    for (size_t i = 0, q = 0; i < gpu.size(); ++i) {
      const WindowPath& w = *drawn[i];
      EXPECT_EQ(gpu[i].start_record + reference.silhouette_base, w.key) << name << " path " << i;
      EXPECT_EQ(gpu[i].path.closed, w.closed) << name << " path " << i;
      ASSERT_EQ(gpu[i].path.points.size(), w.window.size()) << name << " path " << i;
      for (size_t k = 0; k < w.window.size(); ++k, ++q) {
        glm::dvec2 g(points.data[3 * q], points.data[3 * q + 1]);
        worst = std::max(worst, glm::distance(g, w.window[k]));
        EXPECT_EQ(gpu[i].path.points[k].position, w.surface[k].position) << name << " path " << i << " point " << k;
      }
    }
    std::printf("[GPU frame %s] points at most %.3g px from the reference's\n", name.c_str(), worst);
    EXPECT_LT(worst, kSegmentEndPx) << name;
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
  std::vector<const WindowPath*> silhouettes;
  for (const WindowPath& w : lines.paths)
    if (w.kind == LineKind::Silhouette) silhouettes.push_back(&w);
  ASSERT_EQ(silhouettes.size(), 1u);
  EXPECT_EQ(silhouettes[0]->key, lines.silhouette_base + start);
  EXPECT_EQ(silhouettes[0]->window.size(), 2u);
}

}  // namespace
}  // namespace plumbago
