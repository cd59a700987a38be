// G-buffer parity, raster (gpu/gbuffer.cpp) vs ray tracing (reference/gbuffer.cpp),
// SPEC §5: interior pixels agree within 1e-4 in depth and 1e-3 in normals; differences
// only in the one-pixel band along depth discontinuities, whose share is printed.
#include <gtest/gtest.h>

#include "apps/parity.hpp"
#include "tests/test_scenes.hpp"

namespace plumbago {
namespace {

void expect_gbuffer_parity(const Scene& scene, const std::string& label) {
  auto results = run_parity(scene, {"gbuffer"});
  ASSERT_FALSE(results.empty());
  for (const StageParity& r : results) {
    std::printf("[gbuffer %s] %s  [%s]\n", label.c_str(), format_diff(r.name, r.diff).c_str(), r.note.c_str());
    EXPECT_GT(r.diff.compared, scene.width * scene.height / 20) << r.name << ": too few interior pixels to mean anything";
    EXPECT_TRUE(r.pass) << r.name;
    EXPECT_FALSE(has_non_finite(r.gpu)) << r.name;
    EXPECT_FALSE(has_non_finite(r.reference)) << r.name;
  }
}

class GBufferParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(GBufferParity, BuiltinScene) { expect_gbuffer_parity(testing::builtin_at(GetParam(), 400, 300), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Builtin, GBufferParity, ::testing::Values("torus", "sphere", "cad"));

TEST_F(GBufferParity, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  expect_gbuffer_parity(testing::model_scene("fandisk.obj", 800, 800), "fandisk");
}

TEST_F(GBufferParity, StanfordBunny) {
  PLUMBAGO_REQUIRE_MODEL("stanford-bunny.obj");
  expect_gbuffer_parity(testing::model_scene("stanford-bunny.obj", 800, 800), "stanford-bunny");
}

}  // namespace
}  // namespace plumbago
