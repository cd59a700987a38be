// plumbago curvature MESH [--method auto|tensor|jet] [--radius R] [-o out.csv] [--quiet]
//                         [--no-cache] [--set curvature.name=value ...]
// Principal curvature per vertex (Lee et al. 2006, §5.3; Alliez et al. 2003) as CSV, one row per vertex of the mesh as
// loaded (after welding); `firmness` is direction_firmness (0: the directions were
// propagated from the neighbors, 1: the estimate's, held fixed).
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "apps/command.hpp"
#include "common/core/params.hpp"
#include "common/curvature/curvature.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

struct CurvatureCommandOptions {
  std::string mesh, output, method;
  std::optional<double> radius;
  std::vector<std::string> assignments;
  bool quiet = false, no_cache = false;
};

const char* const kHeader = "vertex,x,y,z,nx,ny,nz,k_min,k_max,dmin_x,dmin_y,dmin_z,dmax_x,dmax_y,dmax_z,firmness\n";

// Shortest text that reads back as the same float.
void append_number(std::string& out, float value) {
  char buffer[32];
  auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  out.push_back(',');
  out.append(buffer, end);
}

// A coordinate in the file's frame (Mesh::origin + the centered position): as a float
// where float holds it to within the mesh's own precision, else in double (a file far from
// the origin, whose float would be off by more than its vertices' spacing).
void append_coordinate(std::string& out, double value, double precision) {
  if (std::abs(double(float(value)) - value) <= precision) return append_number(out, float(value));
  char buffer[32];
  auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  out.push_back(',');
  out.append(buffer, end);
}

void write_csv(std::FILE* out, const Mesh& mesh, const Curvature& c, const CurvatureParams& p) {
  float diagonal = mesh.bbox_diagonal();
  const double precision = std::ldexp(double(diagonal), -24);
  std::fputs(kHeader, out);
  std::string row;
  for (size_t v = 0; v < c.size(); ++v) {
    row = std::to_string(v);
    for (int k = 0; k < 3; ++k) append_coordinate(row, mesh.origin[k] + double(mesh.positions[v][k]), precision);
    for (int k = 0; k < 3; ++k) append_number(row, c.normal[v][k]);
    append_number(row, c.k_min[v]);
    append_number(row, c.k_max[v]);
    for (int k = 0; k < 3; ++k) append_number(row, c.d_min[v][k]);
    for (int k = 0; k < 3; ++k) append_number(row, c.d_max[v][k]);
    append_number(row, float(direction_firmness(c.k_min[v], c.k_max[v], p, diagonal)));
    row.push_back('\n');
    std::fwrite(row.data(), 1, row.size(), out);
  }
}

CurvatureParams params_from(const CurvatureCommandOptions& o) {
  ParamSet set;
  try {
    for (const auto& a : o.assignments) set.set_assignment(a);
    if (!o.method.empty()) set.set("curvature.method", o.method);
    if (o.radius) set.set("curvature.radius", *o.radius);
  } catch (const ParamError& e) {
    throw ParamError(std::string("curvature: ") + e.what());
  }
  return set.get<CurvatureParams>();
}

void run(const CurvatureCommandOptions& o) {
  CurvatureParams params = params_from(o);
  Mesh mesh = load_mesh(o.mesh);
  CurvatureOptions options;
  options.use_cache = !o.no_cache;
  options.progress = !o.quiet;
  auto start = std::chrono::steady_clock::now();
  Curvature c = compute_curvature(mesh, params, options);
  std::chrono::duration<double, std::milli> ms = std::chrono::steady_clock::now() - start;
  if (!o.quiet)
    std::fprintf(stderr, "plumbago curvature: %s: %zu vertices, %s, %.1f ms\n", o.mesh.c_str(), c.size(),
                 method_name(resolved_method(mesh, params)), ms.count());
  if (o.output.empty()) {
    write_csv(stdout, mesh, c, params);
    return;
  }
  OutputFile file(o.output);
  std::FILE* out = std::fopen(file.temporary_path().c_str(), "wb");
  if (!out) throw std::runtime_error(o.output + ": cannot be written");
  write_csv(out, mesh, c, params);
  bool written = std::ferror(out) == 0;
  written = std::fclose(out) == 0 && written;
  if (!written) throw std::runtime_error(o.output + ": write failed");
  file.commit();
}

void setup(CLI::App& app) {
  auto o = std::make_shared<CurvatureCommandOptions>();
  auto* cmd = app.add_subcommand("curvature",
                                 "Principal curvature per vertex of a mesh, as CSV (Lee et al. 2006, "
                                 "§5.3; Alliez et al. 2003)");
  cmd->add_option("mesh", o->mesh, "Mesh file (OBJ, OFF, PLY, STL)")->required();
  cmd->add_option(
      "--method", o->method,
      "auto (the default: tensor, or jet on folded meshes), tensor (Cohen-Steiner/Morvan, the paper's) or jet");
  cmd->add_option("--radius", o->radius, "tensor ball radius x bbox diagonal; 0 = 1-ring (curvature.radius)");
  cmd->add_option("-o,--output", o->output, "CSV file to write (default: standard output)");
  cmd->add_option("--set", o->assignments,
                  "Override a parameter: curvature.name=value (see `plumbago params curvature`)");
  cmd->add_flag("--quiet", o->quiet, "No progress or summary on standard error");
  cmd->add_flag("--no-cache", o->no_cache, "Neither read nor write the curvature cache");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago
