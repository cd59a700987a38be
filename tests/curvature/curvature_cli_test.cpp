// `plumbago curvature`: the program run as a user would, its CSV, its options and its
// refusals.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/curvature/curvature.hpp"
#include "common/mesh/mesh.hpp"
#include "tests/support/analytic_surfaces.hpp"
#include "tests/support/curvature_checks.hpp"

namespace plumbago {
namespace {

using namespace plumbago::testing;
namespace fs = std::filesystem;

class CurvatureCli : public ::testing::Test {
 protected:
  struct Run {
    int code;
    std::string out, err;
  };
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("plumbago-curvature-cli-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    mesh_ = analytic_torus(1.0, 0.4, 0.15, Meshing::Irregular).mesh;
    std::ofstream obj(path("torus.obj"));
    for (const auto& p : mesh_.positions) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : mesh_.triangles) obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string slurp(const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  Run run(const std::string& args) const {
    std::string cmd = "PLUMBAGO_CACHE_DIR=" + path("cache") + " " + PLUMBAGO_CLI + " curvature " + args + " >" +
                      path("stdout") + " 2>" + path("stderr");
    int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(path("stdout")), slurp(path("stderr"))};
  }
  static std::vector<std::vector<double>> rows(const std::string& csv) {
    std::vector<std::vector<double>> out;
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);  // header
    while (std::getline(lines, line)) {
      std::vector<double> row;
      std::istringstream fields(line);
      for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
      out.push_back(row);
    }
    return out;
  }

  fs::path dir_;
  Mesh mesh_;
};

TEST_F(CurvatureCli, WritesOneUnitRowPerVertexUnderTheExactHeader) {
  Run r = run(path("torus.obj") + " -o " + path("out.csv") + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::string csv = slurp(path("out.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "vertex,x,y,z,nx,ny,nz,k_min,k_max,dmin_x,dmin_y,dmin_z,dmax_x,dmax_y,dmax_z,firmness");
  auto table = rows(csv);
  ASSERT_EQ(table.size(), mesh_.positions.size());
  CurvatureParams params = curvature_params();
  Curvature c = estimate_curvature(load_mesh(path("torus.obj")), params);
  float diagonal = load_mesh(path("torus.obj")).bbox_diagonal();
  for (size_t v = 0; v < table.size(); ++v) {
    const auto& row = table[v];
    ASSERT_EQ(row.size(), 16u) << v;
    EXPECT_EQ(row[0], double(v));
    EXPECT_NEAR(row[1], mesh_.positions[v].x, 1e-5);
    EXPECT_FLOAT_EQ(float(row[7]), c.k_min[v]) << v;
    EXPECT_FLOAT_EQ(float(row[8]), c.k_max[v]) << v;
    EXPECT_FLOAT_EQ(float(row[15]), float(direction_firmness(c.k_min[v], c.k_max[v], params, diagonal))) << v;
    for (int first : {4, 9, 12}) EXPECT_NEAR(std::hypot(row[first], row[first + 1], row[first + 2]), 1.0, 1e-5) << v;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(path("cache")), fs::directory_iterator()), 1);
}

TEST_F(CurvatureCli, MethodRadiusAndSetReachTheComputation) {
  ASSERT_EQ(run(path("torus.obj") + " --quiet --no-cache").code, 0);
  std::string tensor = slurp(path("stdout"));
  ASSERT_EQ(run(path("torus.obj") + " --quiet --no-cache --method jet").code, 0);
  EXPECT_TRUE(slurp(path("stdout")) != tensor) << "--method jet changed nothing";
  ASSERT_EQ(run(path("torus.obj") + " --quiet --no-cache --radius 0.1").code, 0);  // the default is the 1-ring here
  std::string wide = slurp(path("stdout"));
  EXPECT_TRUE(wide != tensor) << "--radius 0.1 changed nothing";
  ASSERT_EQ(run(path("torus.obj") + " --quiet --no-cache --set curvature.radius=0.1").code, 0);
  EXPECT_TRUE(slurp(path("stdout")) == wide) << "--radius and --set curvature.radius differ";
  EXPECT_FALSE(fs::exists(path("cache")));
}

TEST_F(CurvatureCli, ReportsOnStandardErrorUnlessQuiet) {
  Run r = run(path("torus.obj") + " -o " + path("out.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("vertices, tensor"), std::string::npos) << r.err;
}

TEST_F(CurvatureCli, RefusesBadInputAndLeavesNoFile) {
  std::ofstream(path("bad.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
  const std::pair<std::string, std::string> cases[] = {
      {path("missing.obj"), "missing.obj"},
      {path("bad.obj"), "bad.obj"},
      {path("torus.obj") + " --method magic", "curvature.method"},
      {path("torus.obj") + " --radius 2", "curvature.radius"},
      {path("torus.obj") + " --set curvature.jet_degree=9", "curvature.jet_degree"},
      {path("torus.obj") + " --set curvature.nope=1", "curvature.nope"}};
  for (const auto& [args, needle] : cases) {
    Run r = run(args + " -o " + path("out.csv"));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("out.csv"))) << args;
  }
}

}  // namespace
}  // namespace plumbago
