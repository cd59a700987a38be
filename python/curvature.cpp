// curvature(): principal curvature per vertex, what `plumbago curvature` writes as CSV.
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "common/core/frame.hpp"
#include "common/curvature/curvature.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/values.hpp"

namespace plumbago::python {
namespace {

using namespace py::literals;

CurvatureParams curvature_params(const py::kwargs& params) {
  ParamSet set;
  for (auto [name, value] : params) set_param(set, "curvature." + py::str(name).cast<std::string>(), value);
  return set.get<CurvatureParams>();
}

py::dict curvature(const std::filesystem::path& path, bool cache, const py::kwargs& kwargs) {
  CurvatureParams params = curvature_params(kwargs);
  Mesh mesh;
  Curvature c;
  double ms = 0;
  {
    py::gil_scoped_release free;
    mesh = load_mesh(path.string());
    Stopwatch watch;
    c = compute_curvature(mesh, params, CurvatureOptions{cache, "", false});
    ms = watch.ms();
  }
  std::vector<float> firmness(c.size());
  float diagonal = mesh.bbox_diagonal();
  for (size_t v = 0; v < c.size(); ++v)
    firmness[v] = float(direction_firmness(c.k_min[v], c.k_max[v], params, diagonal));
  std::string method = method_name(resolved_method(mesh, params));
  // In the file's coordinates, as before load_mesh centered them (Mesh::origin).
  for (glm::vec3& p : mesh.positions) p = glm::vec3(mesh.origin + glm::dvec3(p));
  return py::dict("positions"_a = vector_array<float>(std::move(mesh.positions)),
                  "triangles"_a = vector_array<uint32_t>(std::move(mesh.triangles)),
                  "normal"_a = vector_array<float>(std::move(c.normal)), "k_min"_a = vector_array<float>(c.k_min),
                  "k_max"_a = vector_array<float>(c.k_max), "d_min"_a = vector_array<float>(std::move(c.d_min)),
                  "d_max"_a = vector_array<float>(std::move(c.d_max)),
                  "firmness"_a = vector_array<float>(std::move(firmness)), "method"_a = method, "ms"_a = ms);
}

}  // namespace

void bind_curvature(py::module_& m) {
  m.def("curvature", &curvature, py::arg("mesh"), py::kw_only(), py::arg("cache") = true,
        R"(Principal curvature per vertex of a mesh file (OBJ, OFF, PLY, STL), as `plumbago curvature`
computes it (Lee et al. 2006, §5.3; Alliez et al. 2003), one row per vertex of the mesh as
loaded (welded). Keyword arguments set the curvature stage's parameters by name
(method="jet", radius=0.02, direction_smoothing=0; see params("curvature")); cache=False
neither reads nor writes the on-disk cache.

Returns {positions, normal, d_min, d_max: (n, 3) float32; k_min, k_max, firmness: (n,)
float32; triangles: (f, 3) uint32, the welded mesh's faces; method: the estimator used;
ms: the computation's time}. firmness is 0 where the directions were propagated from the
neighbours, 1 where the estimate's were held fixed. MeshError (a ValueError) names the
file and what is wrong with it; ValueError names a bad parameter.)");
}

}  // namespace plumbago::python
