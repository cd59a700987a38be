// Writing a scene back as a scene file (save_scene, common/scene/scene.hpp): what `plumbago
// view` saves, and what `plumbago render` then reproduces.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"
#include "common/util/output_file.hpp"

namespace plumbago {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

json vec3(glm::dvec3 v) { return json::array({v.x, v.y, v.z}); }

// The camera in world space: `c` is relative to the scene's origin.
json camera_json(const Camera& c, glm::dvec3 origin) {
  return {{"eye", vec3(glm::dvec3(c.eye) + origin)},
          {"target", vec3(glm::dvec3(c.target) + origin)},
          {"up", vec3(c.up)},
          {"fov_deg", c.fov_deg},
          {"near", c.near},
          {"far", c.far}};
}

json lights_json(const std::vector<Light>& lights) {
  json out = json::array();
  for (const Light& l : lights) out.push_back({{"direction", vec3(l.direction)}, {"intensity", l.intensity}});
  return out;
}

json params_json(const ParamSet& params) {
  json out = json::object();
  for (const auto& [key, value] : params.overrides()) {
    const ParamSpec& spec = param_spec(key);
    switch (spec.type) {
      case ParamType::Boolean:
        out[key] = value != 0;
        break;
      case ParamType::Choice:
        out[key] = spec.choices.at(size_t(value));
        break;
      case ParamType::Integer:
        out[key] = int64_t(value);
        break;
      case ParamType::Real:
        out[key] = value;
        break;
    }
  }
  return out;
}

// Rewrites a relative file path of the source document (relative to `from`) so that it
// names the same file from `to`.
class Rebase {
 public:
  Rebase(const std::string& from, const std::string& to) : from_(fs::absolute(from)), to_(fs::absolute(to)) {}
  void operator()(json& path) const {
    if (!path.is_string() || fs::path(path.get<std::string>()).is_absolute()) return;
    fs::path file = (from_ / path.get<std::string>()).lexically_normal();
    path = file.lexically_relative(to_).string();
  }

 private:
  fs::path from_, to_;
};

// The document's objects as an "objects" array (a one-mesh document's "mesh" becomes
// its only object), with the scene's styles and rebased mesh paths.
void set_objects(json& doc, const Scene& scene, const Rebase& rebase) {
  if (doc.contains("mesh")) {
    doc["objects"] = json::array({{{"mesh", doc["mesh"]}}});
    doc.erase("mesh");
  }
  json& objects = doc["objects"];
  if (!objects.is_array() || objects.size() != scene.objects.size())
    throw SceneError(scene.source + ": its objects changed on disk since it was loaded; not saved");
  for (size_t i = 0; i < objects.size(); ++i) {
    json& mesh = objects[i]["mesh"];
    rebase(mesh.is_object() && mesh.contains("file") ? mesh["file"] : mesh);
    objects[i]["style"] = style_names().at(size_t(scene.objects[i].style));
  }
}

// Stroke style files (a name with a '/' or ending in .json) are relative to the scene.
void rebase_stroke_styles(json& doc, const Rebase& rebase) {
  if (!doc.contains("strokes")) return;
  for (auto& [key, style] : doc["strokes"].items()) {
    std::string name = style.is_string() ? style.get<std::string>() : "";
    if (name.find('/') != std::string::npos || name.ends_with(".json")) rebase(style);
  }
}

// Stroke files (Kalnins et al. 2002, §3, §4.5) are relative to the scene; the scene's files
// past the document's (drawn in the viewer, apps/viewer/drawing.hpp) are added, each by
// the path it was written to, which must hold it.
void set_stroke_files(json& doc, const Scene& scene, const Rebase& rebase, const fs::path& folder) {
  json& files = doc["stroke_files"];
  if (!files.is_array()) files = json::array();
  for (json& file : files) rebase(file);
  const fs::path to = fs::absolute(folder).lexically_normal();
  for (size_t i = files.size(); i < scene.stroke_files.size(); ++i) {
    const std::string& source = scene.stroke_files[i].source;
    if (!fs::is_regular_file(source))
      throw SceneError(scene.source + ": stroke file " + std::to_string(i) + " " + source +
                       " is not on disk (save the drawn strokes first); not saved");
    files.push_back(fs::absolute(source).lexically_normal().lexically_relative(to).string());
  }
  if (files.empty()) doc.erase("stroke_files");
}

}  // namespace

void save_scene(const Scene& scene, const std::string& path) {
  json doc = json::parse(scene_text(scene.source), nullptr, false);
  if (doc.is_discarded()) throw SceneError(scene.source + ": no longer valid JSON on disk; not saved");
  fs::path folder = fs::path(path).parent_path();
  Rebase rebase(scene_folder(scene.source), folder.empty() ? "." : folder.string());
  set_objects(doc, scene, rebase);
  rebase_stroke_styles(doc, rebase);
  set_stroke_files(doc, scene, rebase, folder.empty() ? fs::path(".") : folder);
  doc["camera"] = camera_json(scene.camera, scene.origin);
  doc["lights"] = lights_json(scene.lights);
  doc["resolution"] = {scene.width, scene.height};
  doc["seed"] = scene.seed;
  doc["effects"] = scene.effects;
  doc["params"] = params_json(scene.params);
  OutputFile out(path);
  std::ofstream file(out.temporary_path());
  file << doc.dump(2) << "\n";
  file.close();
  if (!file) throw SceneError(path + ": cannot write the scene file");
  out.commit();
}

}  // namespace plumbago
