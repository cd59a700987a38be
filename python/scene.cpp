// Scene: a scene opened once, changed in place, rendered, compared, measured.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "common/scene/open_scene.hpp"
#include "common/strokes/strokes.hpp"
#include "common/util/memory_budget.hpp"
#include "parity/bench.hpp"
#include "parity/lines.hpp"
#include "parity/parity.hpp"
#include "parity/path_frames.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/gpu_turn.hpp"
#include "python/values.hpp"

namespace plumbago::python {
namespace {

using namespace py::literals;

// A file or "builtin:NAME" (str or path), a scene document (dict; relative paths resolve
// against the working folder), or None for the default built-in scene.
Scene open(const py::object& source) {
  if (source.is_none()) return open_scene("");
  if (py::isinstance<py::dict>(source)) {
    std::string text = py::module_::import("json").attr("dumps")(source).cast<std::string>();
    py::gil_scoped_release free;
    return parse_scene(text, "<dict>", std::filesystem::current_path().string());
  }
  std::string name = py::str(py::module_::import("os").attr("fspath")(source));
  py::gil_scoped_release free;
  return open_scene(name);
}

// Refuses, before anything runs, a frame the scene's camera path lacks and a scene whose
// buffers would not fit the memory budget (common/util/memory_budget.hpp).
void check_frame(const Scene& scene, int frame) {
  int frames = scene.animation ? scene.animation->frames : 1;
  if (frame < 0 || frame >= frames)
    throw std::invalid_argument("frame " + std::to_string(frame) + ": the scene has " + std::to_string(frames) +
                                " frame" + (frames > 1 ? "s (0.." + std::to_string(frames - 1) + ")" : " (0)"));
  check_scene_memory(scene);
}

Frame render_frame(const Scene& scene, const std::string& backend, int frame, bool keep_buffers) {
  bool gpu = is_gpu(backend);
  check_frame(scene, frame);
  py::gil_scoped_release free;
  GpuTurn turn(gpu);
  return PathFrames(scene, backend).render(frame, FrameOptions{keep_buffers});
}

py::array render(const Scene& scene, const std::string& backend, bool linear, int frame) {
  Frame f = render_frame(scene, backend, frame, false);
  if (linear) return image_array(std::move(f.color));
  return png_array(f.color);
}

py::dict stages(const Scene& scene, const std::string& backend, int frame) {
  Frame f = render_frame(scene, backend, frame, true);
  py::dict out;
  for (auto& [name, image] : f.buffers) out[py::str(name)] = image_array(std::move(image));
  return out;
}

py::object compare(const Scene& scene, const std::vector<std::string>& names) {
  check_frame(scene, 0);
  nlohmann::json report;
  {
    py::gil_scoped_release free;
    GpuTurn turn;
    report = parity_report(run_parity(scene, names));
  }
  return from_json(report);
}

py::dict path_entry(const WindowPath& p, const SceneLines& found, glm::dvec3 origin, py::list runs) {
  std::vector<glm::dvec3> world(p.world.size());
  for (size_t k = 0; k < world.size(); ++k) world[k] = glm::dvec3(p.world[k]) + origin;
  std::vector<bool> shown = points_visible(p, found);
  return py::dict("kind"_a = line_kind_name(p.kind), "object"_a = p.object, "closed"_a = p.closed,
                  "front_facing"_a = p.front_facing, "points"_a = vector_array<double>(std::move(world)),
                  "screen"_a = vector_array<double>(p.window),
                  "visible"_a = vector_array<bool>(std::vector<uint8_t>(shown.begin(), shown.end())),
                  "arc_px"_a = vector_array<double>(
                      std::vector<double>(p.arc_px.begin(), p.arc_px.begin() + long(p.window.size()))),
                  "runs"_a = runs);
}

py::list lines(const Scene& scene, const std::string& backend) {
  bool gpu = is_gpu(backend);
  check_frame(scene, 0);
  SceneLines found;
  {
    py::gil_scoped_release free;
    GpuTurn turn(gpu);
    found = scene_lines(scene, backend);
  }
  std::vector<py::list> runs(found.lines.paths.size());
  for (const VisibleRun& r : found.visibility.runs) runs[r.path].append(py::make_tuple(r.s0, r.s1));
  py::list out;
  for (size_t i = 0; i < runs.size(); ++i)
    out.append(path_entry(found.lines.paths[i], found, found.scene.origin, runs[i]));
  return out;
}

py::object bench(const Scene& scene, int frames, const std::string& backend) {
  bool gpu = is_gpu(backend);
  if (frames < 1) throw std::invalid_argument("frames: " + std::to_string(frames) + " is under 1");
  check_frame(scene, 0);
  BenchResult r;
  {
    py::gil_scoped_release free;
    GpuTurn turn(gpu);
    r = bench_scene(scene, backend, frames);
  }
  return from_json(result_json(r));
}

py::object get(const Scene& scene, const std::string& key) {
  return param_value(param_spec(key), scene.params.value(key));
}

void set(Scene& scene, const std::string& key, const py::object& value) { set_param(scene.params, key, value); }

py::tuple size(const Scene& s) { return py::make_tuple(s.width, s.height); }

void resize(Scene& s, const std::pair<int, int>& size) { resize_scene(s, size.first, size.second, "size"); }

std::string repr(const Scene& s) {
  return "plumbago.Scene('" + s.source + "', size=(" + std::to_string(s.width) + ", " + std::to_string(s.height) +
         "), " + std::to_string(s.objects.size()) + " objects)";
}

const char* const kSceneDoc = R"(A scene: what to draw, from where, in which styles, with which effects and
parameters (docs/scene-format.md).

Scene(source=None): a scene file (str or path), "builtin:NAME" (torus, sphere, cad, pencil,
...), a scene document as a dict (relative paths against the working folder), or None for
builtin:pencil. A file refused raises SceneError (a ValueError) naming the file and line or
the key, MeshError naming the mesh file; nothing is made.

Change it in place (size, set()) and render it as often as you like: each call renders from
scratch, as the command line does. The GPU backend's GL context is made once per process,
headless; calls release the GIL.)";

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", kSceneDoc)
      .def(py::init(&open), py::arg("source") = py::none())
      .def_readonly("source", &Scene::source, "The scene file, \"builtin:NAME\" or \"<dict>\".")
      .def_property("size", &size, &resize,
                    "The image size (width, height), 1..16384 each; a size the camera's field of view\n"
                    "cannot span is refused (ValueError) and the scene kept as it was.")
      .def_property_readonly(
          "frames", [](const Scene& s) { return s.animation ? s.animation->frames : 1; },
          "The frames of the scene's camera path (1 without one).")
      .def_property_readonly(
          "effects", [](const Scene& s) { return s.effects; }, "The effects the scene asks for (see effects()).")
      .def("set", &set, py::arg("key"), py::arg("value"),
           "Sets parameter key (\"stage.name\", see params()) to a number, a bool or a choice's name, as\n"
           "`--set key=value` does. A bad key or value raises ValueError naming it; the scene is kept.")
      .def("get", &get, py::arg("key"), "The value of parameter key: the scene's, or the default.")
      .def("render", &render, py::arg("backend") = "gpu", py::kw_only(), py::arg("linear") = false,
           py::arg("frame") = 0,
           "Renders the scene on backend \"gpu\" (GLSL) or \"reference\" (CPU) and returns the image, top\n"
           "row first: H x W x C uint8, the bytes `plumbago render -o x.png` writes, or with\n"
           "linear=True H x W x C float32, the values of `-o x.exr`, a view of the frame's memory.\n"
           "frame: the frame of the scene's camera path.")
      .def("stages", &stages, py::arg("backend") = "gpu", py::kw_only(), py::arg("frame") = 0,
           "Renders the scene and returns every intermediate buffer by name ({\"gbuffer.normal\": H x W x 3\n"
           "float32, ...}), the values `plumbago render --dump-stages DIR` writes as <backend>.<name>.exr,\n"
           "top row first, views of the frame's memory.")
      .def("compare", &compare, py::arg("stages") = std::vector<std::string>{},
           "Runs each stage (all, or those named) on both backends with the same inputs and compares their\n"
           "outputs, as `plumbago compare --json` does: {pass, renderer, stages: [{name, pass, max_abs, rmse,\n"
           "over_tolerance, tolerance, compared_pixels, bounded_pixels, note}]}.")
      .def("lines", &lines, py::arg("backend") = "gpu",
           "The feature lines of every object but the sketchy ones and the decals, at the scene's camera,\n"
           "with their visibility from the backend's ID image, as `plumbago lines -o x.json` writes them:\n"
           "[{kind, object, closed, front_facing, points: (n, 3) world, screen: (n, 2) pixels from the\n"
           "bottom left, visible: (n,) bool, arc_px: (n,) window arc length, runs: [(s0, s1), ...] the\n"
           "visible runs the strokes draw, in arc px}].")
      .def("bench", &bench, py::arg("frames") = 20, py::arg("backend") = "gpu",
           "Times frames frames on one backend, as `plumbago bench --json` does (a scene with a camera path:\n"
           "each of its frames once): {frame_ms (median), fps, stages: {pass: mean ms}, preprocessing,\n"
           "counts, ...}.")
      .def(
          "save", [](const Scene& s, const std::filesystem::path& p) { save_scene(s, p.string()); }, py::arg("path"),
          "Writes the scene as a scene file that Scene(path) reads back the same.")
      .def("__repr__", &repr);
}

}  // namespace plumbago::python
