// The on-disk curvature cache (common/curvature/curvature_cache.hpp): what it writes and reads
// back, its key, corrupt and stale files, and where it lives.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/curvature/curvature_cache.hpp"
#include "tests/support/analytic_surfaces.hpp"
#include "tests/support/curvature_checks.hpp"

namespace plumbago {
namespace {

using namespace plumbago::testing;
namespace fs = std::filesystem;

class CurvatureCache : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("plumbago-curvature-cache-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    options_.cache_dir = dir_.string();
    options_.progress = false;
    mesh_ = analytic_torus(1.0, 0.4, 0.1, Meshing::Irregular).mesh;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<fs::path> files() const {
    std::vector<fs::path> out;
    if (fs::exists(dir_))
      for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path());
    return out;
  }
  std::string cache_file(const Mesh& mesh, const CurvatureParams& p) const {
    CurvatureCacheKey key{mesh_content_hash(mesh), mesh.positions.size(), curvature_params_key(p)};
    return (dir_ / key.file_name()).string();
  }
  static void expect_same(const Curvature& a, const Curvature& b) {
    EXPECT_EQ(a.k_min, b.k_min);
    EXPECT_EQ(a.k_max, b.k_max);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.d_min, b.d_min);
    EXPECT_EQ(a.d_max, b.d_max);
  }

  fs::path dir_;
  CurvatureOptions options_;
  Mesh mesh_;
};

TEST_F(CurvatureCache, SecondCallReadsWhatTheFirstWrote) {
  CurvatureParams p = curvature_params();
  Curvature first = compute_curvature(mesh_, p, options_);
  ASSERT_EQ(files().size(), 1u);
  EXPECT_EQ(files()[0].string(), cache_file(mesh_, p));
  std::string why;
  auto cached = read_curvature_cache(cache_file(mesh_, p),
                                     {mesh_content_hash(mesh_), mesh_.positions.size(), curvature_params_key(p)}, why);
  ASSERT_TRUE(cached.has_value()) << why;
  expect_same(*cached, first);
  expect_same(compute_curvature(mesh_, p, options_), estimate_curvature(mesh_, p));
}

TEST_F(CurvatureCache, KeyChangesWithTheMeshTheMethodAndEachParameter) {
  CurvatureParams p = curvature_params();
  std::string base = cache_file(mesh_, p);
  Mesh moved = mesh_;
  moved.positions[7].x += 1e-3f;
  EXPECT_NE(cache_file(moved, p), base);
  for (const char* change : {"curvature.method=jet", "curvature.radius=0.02", "curvature.jet_degree=3",
                             "curvature.umbilic_ratio=0.2", "curvature.normal=tensor", "curvature.ring_fallback=false"})
    EXPECT_NE(cache_file(mesh_, curvature_params({change})), base) << change;
}

TEST_F(CurvatureCache, CorruptFilesAreDetectedAndRecomputed) {
  CurvatureParams p = curvature_params();
  Curvature truth = estimate_curvature(mesh_, p);
  std::string path = cache_file(mesh_, p);
  compute_curvature(mesh_, p, options_);
  std::string good;
  {
    std::ifstream in(path, std::ios::binary);
    good.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string flipped = good, nan_value;
  flipped[good.size() / 2] ^= 0x10;
  Curvature with_nan = truth;
  with_nan.k_min[3] = std::nanf("");
  write_curvature_cache(path, {mesh_content_hash(mesh_), mesh_.positions.size(), curvature_params_key(p)}, with_nan);
  {
    std::ifstream in(path, std::ios::binary);  // a NaN under a valid checksum
    nan_value.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (const auto& [what, bytes] : std::map<std::string, std::string>{{"flipped byte", flipped},
                                                                      {"truncated", good.substr(0, good.size() / 3)},
                                                                      {"empty", ""},
                                                                      {"not a cache file", "hello"},
                                                                      {"NaN", nan_value}}) {
    std::ofstream(path, std::ios::binary) << bytes;
    std::string why;
    EXPECT_FALSE(
        read_curvature_cache(path, {mesh_content_hash(mesh_), mesh_.positions.size(), curvature_params_key(p)}, why)
            .has_value())
        << what;
    EXPECT_FALSE(why.empty()) << what;
    expect_same(compute_curvature(mesh_, p, options_), truth);
    std::ifstream in(path, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), good)
        << what << ": not rewritten";
  }
}

TEST_F(CurvatureCache, StaleFileIsRecomputed) {
  CurvatureParams p = curvature_params();
  Mesh other = analytic_sphere(1.0, 0.2, Meshing::Regular).mesh;
  CurvatureCacheKey other_key{mesh_content_hash(other), other.positions.size(), curvature_params_key(p)};
  fs::create_directories(dir_);
  // Another mesh's curvature under this mesh's file name, and this mesh's under other parameters.
  write_curvature_cache(cache_file(mesh_, p), other_key, estimate_curvature(other, p));
  expect_same(compute_curvature(mesh_, p, options_), estimate_curvature(mesh_, p));
  CurvatureParams jet = curvature_params({"curvature.method=jet"});
  write_curvature_cache(cache_file(mesh_, jet),
                        {mesh_content_hash(mesh_), mesh_.positions.size(), curvature_params_key(p)},
                        estimate_curvature(mesh_, p));
  expect_same(compute_curvature(mesh_, jet, options_), estimate_curvature(mesh_, jet));
}

TEST_F(CurvatureCache, DisabledCacheWritesNothing) {
  CurvatureOptions off = options_;
  off.use_cache = false;
  compute_curvature(mesh_, curvature_params(), off);
  EXPECT_TRUE(files().empty());
}

TEST(CurvatureCacheDir, FromTheEnvironmentInOrder) {
  auto saved = [](const char* name) {
    const char* v = std::getenv(name);
    return v ? std::optional<std::string>(v) : std::nullopt;
  };
  auto restore = [](const char* name, const std::optional<std::string>& v) {
    if (v)
      ::setenv(name, v->c_str(), 1);
    else
      ::unsetenv(name);
  };
  auto plumbago = saved("PLUMBAGO_CACHE_DIR"), xdg = saved("XDG_CACHE_HOME"), home = saved("HOME");
  ::setenv("PLUMBAGO_CACHE_DIR", "/tmp/a", 1);
  ::setenv("XDG_CACHE_HOME", "/tmp/b", 1);
  ::setenv("HOME", "/tmp/c", 1);
  EXPECT_EQ(curvature_cache_dir(), "/tmp/a");
  ::unsetenv("PLUMBAGO_CACHE_DIR");
  EXPECT_EQ(curvature_cache_dir(), "/tmp/b/plumbago");
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(curvature_cache_dir(), "/tmp/c/.cache/plumbago");
  restore("PLUMBAGO_CACHE_DIR", plumbago);
  restore("XDG_CACHE_HOME", xdg);
  restore("HOME", home);
}

}  // namespace
}  // namespace plumbago
