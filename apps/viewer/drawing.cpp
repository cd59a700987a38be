// Drawing on the model: see apps/viewer/drawing.hpp.
#include "apps/viewer/drawing.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/strokes/strokes.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

bool same_view(const Camera& a, const Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_deg == b.fov_deg && a.near == b.near &&
         a.far == b.far;
}

// A style named by file, made absolute where drawn (so that a save elsewhere still finds it).
std::string style_reference(const std::string& name) {
  return name.empty() || is_stroke_style_preset(name) ? name : fs::absolute(name).lexically_normal().string();
}

// The path of file `i` of those save() writes to `path`.
std::string numbered(const std::string& path, size_t i) {
  if (i == 0) return path;
  fs::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(i + 1) + p.extension().string())).string();
}

}  // namespace

DrawnStroke drawn_stroke(const Scene& scene, const DrawRequest& request) {
  StrokeFile file;
  file.camera = scene.camera, file.width = scene.width, file.height = scene.height;
  DrawnStroke s;
  const bool on_surface = request.role == StrokeRole::Decal || request.role == StrokeRole::Hatching;
  s.role = request.role, s.points = request.points, s.style_name = on_surface ? style_reference(request.style) : "";
  s.group = request.role == StrokeRole::Hatching ? request.group : -1;
  s.free = request.role == StrokeRole::Hatching && request.free;
  s.mobile = request.role == StrokeRole::Hatching && request.mobile;
  file.strokes.push_back(s);
  // What a stroke file with this one stroke would hold, read back as scenes read them.
  StrokeFile read = parse_stroke_file(stroke_file_json(file, scene.origin), "drawn stroke", ".", scene.origin);
  return read.strokes.at(0);
}

DrawnSurface drawn_surface(const Scene& scene, const DecalSurface& projected) {
  DrawnSurface out;
  std::vector<uint32_t> objects;
  for (const ProjectedDecal& d : projected)
    for (size_t k = 0; k < d.points.size(); ++k) {  // split where a point missed or the object changes
      const DecalPoint& p = d.points[k];
      if (p.object == kMissed || scene.objects[p.object].style != Style::Strokes) continue;
      if (k == 0 || d.points[k - 1].object != p.object) out.polylines.emplace_back();
      out.polylines.back().push_back(p);
      objects.push_back(p.object);
    }
  out.object = most_common_object(objects);
  return out;
}

void Drawing::add(const Scene& scene, DrawnStroke stroke, DrawnSurface surface) {
  drawn_.push_back({scene.camera, scene.width, scene.height, std::move(stroke), std::move(surface)});
  undone_.clear();
  changed();
}

bool Drawing::undo() {
  if (drawn_.empty()) return false;
  undone_.push_back(std::move(drawn_.back()));
  drawn_.pop_back();
  changed();
  return true;
}

bool Drawing::redo() {
  if (undone_.empty()) return false;
  drawn_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  changed();
  return true;
}

void Drawing::erase(size_t stroke) {
  drawn_.erase(drawn_.begin() + std::ptrdiff_t(std::min(stroke, drawn_.size())));
  undone_.clear();
  changed();
}

std::optional<size_t> Drawing::stroke_near(const Scene& scene, glm::dvec2 at, double radius) const {
  const WindowProjection project(scene.camera, scene.width, scene.height);
  std::optional<size_t> nearest;
  double best = radius;
  for (size_t i = 0; i < drawn_.size(); ++i)
    for (const std::vector<DecalPoint>& line : drawn_[i].surface.polylines)
      for (size_t k = 0; k < line.size(); ++k) {
        glm::dvec2 a(project(decal_point_world(scene, line[k])));
        glm::dvec2 b = k + 1 < line.size() ? glm::dvec2(project(decal_point_world(scene, line[k + 1]))) : a;
        double t = glm::clamp(glm::dot(at - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-12), 0.0, 1.0);
        double d = glm::distance(at, a + t * (b - a));
        if (d <= best) best = d, nearest = i;
      }
  return nearest;
}

std::vector<StrokeFile> Drawing::files() const {
  std::vector<StrokeFile> out;
  for (const Drawn& d : drawn_) {
    if (out.empty() || !same_view(out.back().camera, d.camera) || out.back().width != d.width ||
        out.back().height != d.height) {
      out.emplace_back();
      out.back().camera = d.camera, out.back().width = d.width, out.back().height = d.height;
      out.back().source = out.size() <= paths_.size() ? paths_[out.size() - 1]
                                                      : "(drawn in view " + std::to_string(out.size()) + ", not saved)";
    }
    out.back().strokes.push_back(d.stroke);
  }
  return out;
}

std::vector<std::string> Drawing::save(const std::string& path, glm::dvec3 origin) {
  std::vector<StrokeFile> made = files();
  if (made.empty()) throw std::invalid_argument("no drawn strokes to save");
  OutputFiles out;
  std::vector<std::string> paths;
  for (size_t i = 0; i < made.size(); ++i) {
    paths.push_back(numbered(path, i));
    fs::path folder = fs::absolute(paths.back()).parent_path();
    for (DrawnStroke& s : made[i].strokes)  // style files relative to the stroke file
      if (!s.style_name.empty() && !is_stroke_style_preset(s.style_name))
        s.style_name = fs::path(s.style_name).lexically_relative(folder).string();
    std::ofstream(out.add(paths.back()).temporary_path()) << stroke_file_json(made[i], origin);
  }
  out.commit();
  paths_ = paths, saved_ = true;
  return paths;
}

}  // namespace plumbago
