// Golden images (docs/testing.md): every built-in scene and two shared-model scenes,
// rendered on both backends and compared with the 8-bit PNGs in tests/golden/. Parity
// compares the backends with each other; this catches a change that moves both (common/).
// PLUMBAGO_UPDATE_GOLDEN=1 writes the goldens instead (scripts/update-golden.sh).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "common/scene/scene.hpp"
#include "common/util/image.hpp"
#include "common/util/image_compare.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/gl/context.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

// Every golden is rendered at this size (the scene's own resolution is replaced, as
// `plumbago render SCENE --size 200x200` does; all the scenes here are square).
constexpr int kGoldenSize = 200;

// Tolerance, measured (llvmpipe LLVM 15.0.6, 2-core AMD EPYC): 10 renders of each golden
// scene in one process (fresh and reused gpu::Renderer), and renders in separate
// processes under `taskset -c 0` (TBB on one thread), LP_NUM_THREADS=0/1/4/16 and
// LP_NATIVE_VECTOR_WIDTH=128, were bit-identical in float on both backends (reference:
// per-pixel TBB work with nothing summed across threads; llvmpipe: the same JIT code per
// tile whatever the thread count). So the goldens are compared exactly after 8-bit
// quantization: a pixel counts as changed when any channel moves by one level. A real
// change shows: edge.depth_scale 10 -> 11 changes 30% of the cad golden's pixels
// (GoldenSensitivity below).
constexpr double kExactLevel = 0.5 / 255.0;  // over half a level = one 8-bit level or more
constexpr double kExactShare = 0.0;          // no pixel may change
// The reference on another CPU: on a 2-core AMD EPYC (AVX2, FMA; 2026-11-30) the same build
// moved 2, 2, 3 and 23 of the 40,000 pixels of the sphere, pencil, fandisk pencil and
// torus strokes reference goldens by one level (the GPU goldens stayed exact, and so did the
// reference under Embree's SSE4.2, AVX and AVX2 kernels and on one thread: the cause was not
// found). So the reference's goldens let at most 0.1% of the pixels move, by one level at
// most.
constexpr double kCpuShare = 0.001, kCpuMostLevels = 1.0;
// A GPU that is not llvmpipe rounds and filters differently (the goldens are made with
// llvmpipe): its GPU goldens pass when at most 1% of the pixels differ by over 2/255.
// Not measured (no such GPU here); chosen well under the 7.7% that edge.depth_scale
// 10 -> 11 moves over 2/255 on cad, and under end-to-end parity's 5% between backends.
constexpr double kLooseLevel = 2.0 / 255.0;
constexpr double kLooseShare = 0.01;

struct Tolerance {
  double level;  // a pixel differs when a channel differs by more than this
  double share;  // the golden fails when more than this share of pixels differ
  std::string what;
  double most = 1.0;  // or when a channel differs by more than this
};

const Tolerance kExact{kExactLevel, kExactShare, "exact (8-bit)"};
const Tolerance kReferenceCpu{kExactLevel, kCpuShare, "one level in 0.1% of the pixels (8-bit)",
                              (kCpuMostLevels + 0.5) / 255.0};

enum class Backend { Reference, Gpu };
const char* backend_name(Backend b) { return b == Backend::Reference ? "reference" : "gpu"; }

struct GoldenCase {
  std::string name;    // file stem in tests/golden/
  std::string source;  // "builtin:NAME", or a scene file relative to the repository
  std::string model;   // the shared model it needs ("" for none)
};

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.source; }
void PrintTo(Backend b, std::ostream* os) { *os << backend_name(b); }

std::vector<GoldenCase> golden_cases() {
  std::vector<GoldenCase> cases;
  for (const auto& n : builtin_scene_names()) cases.push_back({n, "builtin:" + n, ""});
  cases.push_back({"fandisk_pencil", "scenes/fandisk_pencil.json", "fandisk.obj"});  // every pencil effect
  cases.push_back({"ogre_sketchy", "scenes/ogre_sketchy.json", "ogre.obj"});
  cases.push_back({"torus_strokes", "scenes/torus_strokes.json",
                   ""});  // stroke-based rendering: base coat, paper, silhouette strokes
  return cases;
}

fs::path source_root() { return fs::path(__FILE__).parent_path().parent_path().parent_path(); }  // tests/core/..
fs::path golden_dir() { return source_root() / "tests" / "golden"; }
fs::path golden_path(const std::string& name, Backend b) {
  return golden_dir() / (name + "." + backend_name(b) + ".png");
}

// build/golden-failures/ next to the test binary, or $PLUMBAGO_GOLDEN_FAILURES.
fs::path failures_dir() {
  if (const char* d = std::getenv("PLUMBAGO_GOLDEN_FAILURES"); d && *d) return fs::absolute(d);
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return (ec ? fs::current_path() : exe.parent_path()) / "golden-failures";
}

bool update_mode() {
  const char* v = std::getenv("PLUMBAGO_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

Scene load_golden_scene(const GoldenCase& c) {
  Scene s = c.source.rfind("builtin:", 0) == 0 ? builtin_scene(c.source.substr(8))
                                               : load_scene((source_root() / c.source).string());
  s.width = kGoldenSize;
  s.height = kGoldenSize;
  return s;
}

Image render(const Scene& scene, Backend b) {
  if (b == Backend::Reference) return reference::render(scene).color;
  return gpu::Renderer(scene).render().color;
}

// The image as its PNG holds it: written and read back through write_image/read_image.
Image quantized(const Image& img) {
  fs::path tmp = fs::temp_directory_path() / ("plumbago-golden-" + std::to_string(::getpid()) + ".png");
  write_image(img, tmp.string());
  Image q = read_image(tmp.string());
  fs::remove(tmp);
  return q;
}

bool is_llvmpipe() { return gpu::Context::get().renderer().find("llvmpipe") != std::string::npos; }

Tolerance tolerance_for(Backend b) {
  if (b == Backend::Reference) return kReferenceCpu;
  if (is_llvmpipe()) return kExact;
  return {kLooseLevel, kLooseShare,
          "loose (GPU '" + gpu::Context::get().renderer() + "' is not llvmpipe, which made the goldens)"};
}

struct GoldenResult {
  bool match = false;
  ImageDiff diff;
  std::string summary;
};

// Compares a quantized render with its golden: the check every golden test makes.
GoldenResult compare_with_golden(const Image& golden, const Image& actual, const Tolerance& tol) {
  GoldenResult r;
  if (golden.width != actual.width || golden.height != actual.height || golden.channels != actual.channels) {
    r.summary = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + "x" +
                std::to_string(actual.channels) + ", golden " + std::to_string(golden.width) + "x" +
                std::to_string(golden.height) + "x" + std::to_string(golden.channels);
    return r;
  }
  r.diff = compare_images(golden, actual, tol.level);
  r.match = r.diff.over_tolerance <= tol.share && r.diff.max_abs <= tol.most;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%zu of %zu pixels differ by over %.3g (%.4f%%, allowed %.4f%%), max %.0f/255",
                size_t(r.diff.over_tolerance * double(r.diff.compared) + 0.5), r.diff.compared, tol.level,
                100 * r.diff.over_tolerance, 100 * tol.share, r.diff.max_abs * 255);
  r.summary = buf;
  return r;
}

// The heat map's scale: gray grows with the difference up to this, red above it. (At the
// exact tolerance every changed pixel would be red; this keeps one level visible, 32/255
// gray, and shows where the change is large.)
constexpr double kHeatmapLevel = kLooseLevel;

// Writes NAME.golden.png, NAME.actual.png and NAME.diff.png (the heat map); returns the
// folder.
fs::path write_failure(const std::string& name, const Image& golden, const Image& actual, const Tolerance& tol) {
  fs::path dir = failures_dir();
  fs::create_directories(dir);
  write_image(golden, (dir / (name + ".golden.png")).string());
  write_image(actual, (dir / (name + ".actual.png")).string());
  if (golden.width == actual.width && golden.height == actual.height && golden.channels == actual.channels)
    write_image(diff_heatmap(golden, actual, std::max(tol.level, kHeatmapLevel)),
                (dir / (name + ".diff.png")).string());
  return dir;
}

class GoldenImage : public ::testing::TestWithParam<std::tuple<GoldenCase, Backend>> {
 protected:
  void TearDown() override {
    if (std::get<1>(GetParam()) == Backend::Gpu) {
      EXPECT_NO_THROW(
          gpu::Context::get().check_errors(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    }
  }
};

TEST_P(GoldenImage, Matches) {
  const auto& [c, backend] = GetParam();
  if (!c.model.empty()) {
    PLUMBAGO_REQUIRE_MODEL(c.model) << " (needed by " << c.source << ")";
  }
  const std::string label = c.name + "." + backend_name(backend);
  const fs::path golden_file = golden_path(c.name, backend);
  if (backend == Backend::Gpu) std::printf("[golden] GL renderer: %s\n", gpu::Context::get().renderer().c_str());

  Stopwatch clock;
  Image actual = quantized(render(load_golden_scene(c), backend));
  double ms = clock.ms();

  if (update_mode()) {
    if (backend == Backend::Gpu && !is_llvmpipe())
      FAIL() << "GPU goldens are made with llvmpipe; this GPU is '" << gpu::Context::get().renderer() << "'";
    if (fs::exists(golden_file) && compare_with_golden(read_image(golden_file.string()), actual, kExact).match) {
      std::printf("[golden] %s unchanged (%.0f ms)\n", label.c_str(), ms);
    } else {
      fs::create_directories(golden_dir());
      write_image(actual, golden_file.string());
      std::printf("[golden] wrote %s (%.0f ms)\n", golden_file.c_str(), ms);
    }
    return;
  }

  ASSERT_TRUE(fs::exists(golden_file)) << "no golden " << golden_file
                                       << ": run scripts/update-golden.sh if this scene is new";
  Image golden = read_image(golden_file.string());
  Tolerance tol = tolerance_for(backend);
  GoldenResult r = compare_with_golden(golden, actual, tol);
  std::printf("[golden] %s: %s, tolerance %s (%.0f ms)\n", label.c_str(), r.summary.c_str(), tol.what.c_str(), ms);
  if (!r.match) {
    fs::path dir = write_failure(label, golden, actual, tol);
    ADD_FAILURE() << label << " differs from " << golden_file << ": " << r.summary << ", tolerance " << tol.what
                  << ".\nGolden, actual and diff (heat map: gray up to 2/255, red over): " << (dir / label).string()
                  << ".{golden,actual,diff}.png\nIf the change is intended, run scripts/update-golden.sh and say why "
                     "in the commit (docs/testing.md).";
  }
}

std::string case_name(const ::testing::TestParamInfo<std::tuple<GoldenCase, Backend>>& info) {
  return std::get<0>(info.param).name + "_" + backend_name(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenImage,
                         ::testing::Combine(::testing::ValuesIn(golden_cases()),
                                            ::testing::Values(Backend::Reference, Backend::Gpu)),
                         case_name);

// The comparison is tight enough to see a real change: the cad scene rendered with one
// default parameter moved (edge.depth_scale 10 -> 11) must not match its golden, under
// the exact tolerance and under the loose one a GPU other than llvmpipe gets.
TEST(GoldenSensitivity, OneParameterChangedIsCaught) {
  if (update_mode()) GTEST_SKIP() << "PLUMBAGO_UPDATE_GOLDEN=1: writing goldens, not comparing";
  GoldenCase cad{"cad", "builtin:cad", ""};
  Scene scene = load_golden_scene(cad);
  const double depth_scale = scene.params.value("edge.depth_scale");
  scene.params.set("edge.depth_scale", depth_scale + 1);
  const Tolerance loose{kLooseLevel, kLooseShare, "loose"};
  for (Backend b : {Backend::Reference, Backend::Gpu}) {
    fs::path golden_file = golden_path(cad.name, b);
    ASSERT_TRUE(fs::exists(golden_file)) << "no golden " << golden_file;
    Image golden = read_image(golden_file.string());
    Image changed = quantized(render(scene, b));
    for (const Tolerance& tol : {kExact, loose}) {
      GoldenResult r = compare_with_golden(golden, changed, tol);
      std::printf("[golden] cad.%s with edge.depth_scale %g -> %g, %s: %s\n", backend_name(b), depth_scale,
                  depth_scale + 1, tol.what.c_str(), r.summary.c_str());
      EXPECT_FALSE(r.match) << backend_name(b) << ": edge.depth_scale " << depth_scale << " -> " << depth_scale + 1
                            << " went unnoticed under the " << tol.what << " tolerance: " << r.summary;
    }
  }
  EXPECT_NO_THROW(gpu::Context::get().check_errors("GoldenSensitivity"));
}

}  // namespace
}  // namespace plumbago
