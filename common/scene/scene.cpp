// Scene files (docs/scene-format.md, scenes/scene.schema.json) and the built-in scenes.
#include "common/scene/scene.hpp"
#include "common/scene/json_position.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "common/core/passes.hpp"
#include "common/mesh/decimate.hpp"
#include "common/mesh/procedural.hpp"
#include "common/util/input_file.hpp"

namespace plumbago {

static_assert(kMaxCoordinate == kMaxMeshCoordinate, "a mesh file's bound is the world's");

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Where a fitted camera looks from (world space, towards the camera).
const glm::vec3 kViewDirection(1.0f, 0.7f, 1.6f);

// Bounds of what float buffers can hold (docs/bad-input.md; the camera's in camera.hpp).
// A light's intensity: the sum of 8 lights times any shading parameter stays finite.
constexpr double kMaxLightIntensity = 1e6;
// An object's transform: its linear part A, with condition number |A| |A^-1| (Frobenius
// norms; 3 for a rotation and uniform scale) at most this, and a determinant inside this
// range, so that the normal matrix, computed in float as adjugate / determinant, neither
// overflows nor underflows.
constexpr double kMaxTransformCondition = 1e6;
constexpr double kMinTransformDeterminant = 1e-30, kMaxTransformDeterminant = 1e30;
// A camera path: at most ten turns, 100000 frames, 1000 frames a second.
constexpr double kMaxOrbitDeg = 3600, kMaxFps = 1000;
constexpr int64_t kMaxFrames = 100000;

// The built-in scenes' documents ("builtin:NAME"): one procedural mesh each, in the
// default style and effects, and "pencil", the CAD part with every pencil effect (what
// `plumbago render` draws without a scene).
const std::map<std::string, std::string> kBuiltinScenes = {
    {"torus", R"({"mesh": {"procedural": "torus"}})"},
    {"sphere", R"({"mesh": {"procedural": "sphere"}})"},
    {"cad", R"({"mesh": {"procedural": "cad"}})"},
    {"pencil", R"({"mesh": {"procedural": "cad"}, "effects": ["contours", "interior", "crosshatch", "paper"]})"}};

// "a, b, c": the names a refusal offers.
std::string join(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

// Reads one scene document, naming the file and the JSON path in every refusal.
class SceneReader {
 public:
  SceneReader(std::string source, std::string base_dir) : source_(std::move(source)), base_(std::move(base_dir)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneError(source_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  void only_keys(const json& j, const std::string& path, const std::set<std::string>& allowed) const {
    if (!j.is_object()) fail(path, "expected an object");
    for (const auto& [key, value] : j.items())
      if (!allowed.count(key)) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(path + "/" + key, "unknown key (known here: " + list + ")");
      }
  }

  // A number that float buffers can hold, kept in double: world-space positions are made
  // relative to the scene's origin before they become float.
  double exact_number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "expected a number");
    double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "expected a finite number");
    if (!std::isfinite(float(v))) fail(path, format_number(v) + " is beyond float range (±3.4e38)");
    return v;
  }

  // A number as the buffers hold it: a finite float.
  float number(const json& j, const std::string& path) const { return float(exact_number(j, path)); }

  glm::dvec3 point(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers");
    return {exact_number(j[0], path + "/0"), exact_number(j[1], path + "/1"), exact_number(j[2], path + "/2")};
  }

  glm::vec3 vec3(const json& j, const std::string& path) const { return glm::vec3(point(j, path)); }

  // A vector that is normalized in float: its length within what that can take.
  glm::vec3 direction(const json& j, const std::string& path) const {
    glm::vec3 v = vec3(j, path);
    double length = glm::length(glm::dvec3(v));
    if (length == 0) fail(path, "must not be zero");
    if (length < kMinDirectionLength || length > kMaxDirectionLength)
      fail(path, "has length " + format_number(length) + ", outside [" + format_number(kMinDirectionLength) + ", " +
                     format_number(kMaxDirectionLength) + "]");
    return v;
  }

  // A mesh as the scene holds it: moved so that its bounding box is centered on 0, so that
  // normals and curvature are computed at the mesh's own scale wherever its file puts it,
  // and `center`, where that center lies in the file's coordinates (in double).
  struct PlacedMesh {
    std::shared_ptr<const Mesh> mesh;
    glm::dvec3 center{0.0};
  };

  PlacedMesh mesh(const json& j, const std::string& path) {
    try {
      if (j.is_string()) return mesh_file(j.get<std::string>());
      if (!j.is_object()) fail(path, "expected a mesh file path, {\"file\": PATH} or {\"procedural\": KIND}");
      only_keys(j, path, {"procedural", "resolution", "file", "decimate_to"});
      const size_t faces = j.contains("decimate_to") ? decimate_to(j["decimate_to"], path + "/decimate_to") : 0;
      if (j.contains("file") == j.contains("procedural")) fail(path, "give either \"file\" or \"procedural\"");
      if (j.contains("file")) {
        if (!j["file"].is_string()) fail(path + "/file", "expected a mesh file path");
        if (j.contains("resolution")) fail(path + "/resolution", "applies to a procedural mesh only");
        return mesh_file(j["file"].get<std::string>(), faces);
      }
      if (!j["procedural"].is_string()) fail(path + "/procedural", "expected a name");
      float res = j.contains("resolution") ? number(j["resolution"], path + "/resolution") : 1.0f;
      Mesh m = make_procedural(j["procedural"].get<std::string>(), res);
      return centered(faces ? decimate(m, faces) : std::move(m));
    } catch (const MeshError& e) {
      fail(path, e.what());
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
  }

  // An object as its file gives it: the transform in double, world space (not yet relative
  // to the scene's origin).
  struct FileObject {
    SceneObject object;
    glm::dmat4 transform{1.0};
    glm::dvec3 mesh_center{0.0};  // PlacedMesh::center
    // Where vertex p of the (centered) mesh lies in the file's coordinates.
    glm::dvec3 file_position(glm::vec3 p) const { return glm::dvec3(p) + mesh_center; }
    glm::dvec3 world_position(glm::vec3 p) const { return glm::dvec3(transform * glm::dvec4(file_position(p), 1.0)); }
  };

  FileObject placed(const json& j, const std::string& path) {
    PlacedMesh m = mesh(j, path);
    FileObject f;
    f.object.mesh = m.mesh;
    f.mesh_center = m.center;
    return f;
  }

  FileObject object(const json& j, const std::string& path) {
    only_keys(j, path, {"mesh", "transform", "style", "color", "flat"});
    if (!j.contains("mesh")) fail(path + "/mesh", "missing (a file path or {\"procedural\": ...})");
    FileObject f = placed(j["mesh"], path + "/mesh");
    SceneObject& o = f.object;
    if (j.contains("transform")) f.transform = transform(j["transform"], path + "/transform");
    if (j.contains("style")) o.style = style(j["style"], path + "/style");
    if (j.contains("color")) o.color = color(j["color"], path + "/color");
    if (j.contains("flat")) {
      if (!j["flat"].is_boolean()) fail(path + "/flat", "expected true or false");
      o.flat = j["flat"].get<bool>();
    }
    check_extent(f, path);
    return f;
  }

  // Every vertex within ±kMaxCoordinate, in the mesh file and in the world. |A| |p| + |t|
  // bounds each partial sum of the transform's products, so none overflows in float.
  void check_extent(const FileObject& f, const std::string& path) const {
    const glm::dmat4& t = f.transform;
    glm::dmat4 magnitude;
    for (int c = 0; c < 4; ++c) magnitude[c] = glm::abs(t[c]);
    auto beyond = [](glm::dvec3 p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate; };
    const std::vector<glm::vec3>& positions = f.object.mesh->positions;
    for (size_t i = 0; i < positions.size(); ++i) {
      glm::dvec3 p = f.file_position(positions[i]);
      if (beyond(p))
        fail(path + "/mesh", "vertex " + std::to_string(i) + " lies at " + format_point(p) + beyond_text());
      if (beyond(glm::dvec3(magnitude * glm::dvec4(glm::abs(p), 1.0))))
        fail(path + "/transform", "moves vertex " + std::to_string(i) + " to " +
                                      format_point(f.world_position(positions[i])) + beyond_text());
    }
  }

  Camera camera(const json& j, const std::string& path, const Scene& scene) const {
    only_keys(j, path, {"eye", "target", "up", "fov_deg", "near", "far", "view_direction"});
    glm::vec3 view =
        j.contains("view_direction") ? direction(j["view_direction"], path + "/view_direction") : kViewDirection;
    Camera c = fitted_camera(scene, j.contains("fov_deg") ? number(j["fov_deg"], path + "/fov_deg") : 35.0f, view);
    if (j.contains("eye")) c.eye = glm::vec3(point(j["eye"], path + "/eye") - scene.origin);
    if (j.contains("target")) c.target = glm::vec3(point(j["target"], path + "/target") - scene.origin);
    if (j.contains("up")) c.up = vec3(j["up"], path + "/up");
    if (j.contains("eye") || j.contains("target")) fit_planes(scene, c);
    if (j.contains("near")) c.near = number(j["near"], path + "/near");
    if (j.contains("far")) c.far = number(j["far"], path + "/far");
    return c;
  }

  // Refuses a camera that float buffers cannot render (camera_fault), naming the key and,
  // for a value the scene does not give, where it came from.
  void check_camera(const Scene& s, const json& j, const std::string& path) const {
    static const std::map<std::string, std::string> defaults = {
        {"eye", "where the camera fitted to the scene stands: the scene is too large for the field of view"},
        {"target", "the scene's center"},
        {"up", "the default up"},
        {"near", "fitted to the scene as seen from the eye: the scene is too far from the eye for its size"},
        {"far", "fitted to the scene as seen from the eye: the scene is too far from the eye for its size"}};
    auto fault = camera_fault(s.camera, double(s.width) / s.height, s.origin);
    if (!fault) return;
    bool given = j.contains(fault->key) || !defaults.count(fault->key);
    fail(path + "/" + fault->key, fault->what + (given ? "" : " (" + defaults.at(fault->key) + ")"));
  }

  // "animation": {"orbit_deg": D or "dolly": L, "frames": N, "fps": F}. Every frame's
  // camera is checked as the scene's own is, and a dolly's eye must not reach its target
  // (the view would turn around).
  Animation animation(const json& j, const std::string& path, const Scene& s) const {
    only_keys(j, path, {"orbit_deg", "dolly", "frames", "fps"});
    if (j.contains("orbit_deg") == j.contains("dolly")) fail(path, "give either \"orbit_deg\" or \"dolly\"");
    Animation a;
    std::string key = j.contains("orbit_deg") ? "orbit_deg" : "dolly";
    a.kind = key == "orbit_deg" ? Animation::Kind::Orbit : Animation::Kind::Dolly;
    a.amount = exact_number(j[key], path + "/" + key);
    if (a.kind == Animation::Kind::Orbit && std::abs(a.amount) > kMaxOrbitDeg)
      fail(path + "/orbit_deg", "must be within ±" + format_number(kMaxOrbitDeg) + " degrees");
    if (!j.contains("frames") || !j["frames"].is_number_integer() || j["frames"].get<int64_t>() < 1 ||
        j["frames"].get<int64_t>() > kMaxFrames)
      fail(path + "/frames", "expected a whole number of frames in 1.." + std::to_string(kMaxFrames));
    a.frames = int(j["frames"].get<int64_t>());
    if (j.contains("fps")) a.fps = exact_number(j["fps"], path + "/fps");
    if (!(a.fps > 0 && a.fps <= kMaxFps)) fail(path + "/fps", "must be in (0, " + format_number(kMaxFps) + "]");
    glm::vec3 center;
    float radius;
    scene_bounds(s, center, radius);
    for (int i = 1; i < a.frames; ++i) {
      Camera c = camera_at(s.camera, a, i, center, radius);
      std::string frame = "frame " + std::to_string(i) + "'s camera: ";
      if (a.kind == Animation::Kind::Dolly && glm::dot(glm::dvec3(c.target) - glm::dvec3(c.eye),
                                                       glm::dvec3(s.camera.target) - glm::dvec3(s.camera.eye)) <= 0)
        fail(path + "/dolly", frame + "the eye reaches or passes the target (it moves " + format_number(a.amount) +
                                  " toward a target " + format_number(glm::distance(s.camera.eye, s.camera.target)) +
                                  " away): a dolly must stop short of it");
      if (auto fault = camera_fault(c, double(s.width) / s.height, s.origin))
        fail(path + "/" + key, frame + fault->key + " " + fault->what);
    }
    return a;
  }

  std::vector<Light> lights(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, "expected an array of lights");
    std::vector<Light> out;
    for (size_t i = 0; i < j.size(); ++i) {
      std::string p = path + "/" + std::to_string(i);
      only_keys(j[i], p, {"direction", "intensity"});
      if (!j[i].contains("direction")) fail(p + "/direction", "missing");
      Light l{direction(j[i]["direction"], p + "/direction"), 1.0f};
      if (j[i].contains("intensity")) l.intensity = number(j[i]["intensity"], p + "/intensity");
      if (l.intensity < 0 || l.intensity > kMaxLightIntensity)
        fail(p + "/intensity", "must be in [0, " + format_number(kMaxLightIntensity) + "]");
      out.push_back(l);
    }
    if (out.size() > 8) fail(path, "at most 8 lights");
    return out;
  }

  void resolution(const json& j, const std::string& path, Scene& s) const {
    if (!j.is_array() || j.size() != 2 || !j[0].is_number_integer() || !j[1].is_number_integer())
      fail(path, "expected [width, height] in pixels");
    for (int k = 0; k < 2; ++k)
      if (j[k].get<int64_t>() < 1 || j[k].get<int64_t>() > 16384)
        fail(path + "/" + std::to_string(k), "must be in 1..16384");
    s.width = j[0].get<int>();
    s.height = j[1].get<int>();
  }

  std::vector<std::string> effects(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, "expected an array of effect names");
    std::vector<std::string> out;
    for (size_t i = 0; i < j.size(); ++i) {
      std::string p = path + "/" + std::to_string(i);
      if (!j[i].is_string()) fail(p, "expected an effect name");
      if (!is_effect(j[i].get<std::string>()))
        fail(p, "unknown effect '" + j[i].get<std::string>() + "' (known: " + effect_names() + ")");
      out.push_back(j[i].get<std::string>());
    }
    return out;
  }

  void params(const json& j, const std::string& path, ParamSet& set) const {
    if (!j.is_object()) fail(path, "expected an object of \"stage.name\": value");
    for (const auto& [key, value] : j.items()) {
      std::string p = path + "/" + key;
      try {
        if (value.is_boolean())
          set.set(key, value.get<bool>() ? 1.0 : 0.0);
        else if (value.is_number())
          set.set(key, value.get<double>());
        else if (value.is_string())
          set.set(key, value.get<std::string>());
        else
          fail(p, "expected a number, a boolean or a choice name");
      } catch (const ParamError& e) {
        fail(p, e.what());
      }
    }
  }

  // Looks at the scene's bounding sphere from `direction`, the sphere filling the view.
  static Camera fitted_camera(const Scene& s, float fov, glm::vec3 direction = kViewDirection) {
    glm::vec3 center;
    float radius;
    scene_bounds(s, center, radius);
    return fit_camera(center, radius, direction, fov);
  }

  // "strokes": {"crease": STYLE, "border": STYLE, "silhouette": STYLE}, each a preset name
  // or a style file (relative to the scene's folder).
  StrokeStyles stroke_styles(const json& j, const std::string& path) const {
    only_keys(j, path, {"crease", "border", "silhouette"});
    StrokeStyles out;
    for (auto [key, style] :
         {std::pair{"crease", &out.crease}, {"border", &out.border}, {"silhouette", &out.silhouette}}) {
      if (!j.contains(key)) continue;
      const json& v = j[key];
      if (!v.is_string())
        fail(path + "/" + key, "expected a style name (" + join(stroke_style_names()) + ") or a style file");
      try {
        *style = load_stroke_style_from(v.get<std::string>(), base_);
      } catch (const StrokeStyleError& e) {
        fail(path + "/" + key, e.what());
      }
    }
    return out;
  }

  // "stroke_files": [PATH, ...], relative to the scene's folder (common/strokes/stroke_file.hpp).
  std::vector<StrokeFile> stroke_files(const json& j, const std::string& path, glm::dvec3 origin) const {
    if (!j.is_array()) fail(path, "expected an array of stroke file paths");
    std::vector<StrokeFile> out;
    std::map<std::string, size_t> listed;  // the file (canonical where it exists): its first position
    for (size_t i = 0; i < j.size(); ++i) {
      const std::string key = path + "/" + std::to_string(i);
      if (!j[i].is_string()) fail(key, "expected a stroke file path");
      fs::path file = j[i].get<std::string>();
      fs::path full = file.is_absolute() ? file : fs::path(base_) / file;
      std::error_code error;
      fs::path same = fs::weakly_canonical(full, error);
      // A file listed twice would draw its strokes twice and give every hatching group of it
      // two definitions: said as such, not as a conflict between groups.
      auto [first, added] = listed.emplace((error ? full.lexically_normal() : same).string(), i);
      if (!added)
        fail(key, "'" + j[i].get<std::string>() + "' is listed twice (at " + path + "/" +
                      std::to_string(first->second) + " and " + key + "): list each stroke file once");
      try {  // the file's refusal, through the scene's key
        out.push_back(load_stroke_file(full.string(), origin));
      } catch (const SceneError& e) {
        fail(key, e.what());
      }
    }
    return out;
  }

 private:
  static std::string beyond_text() {
    return ", beyond ±" + format_number(kMaxCoordinate) + " (the largest coordinate float buffers can hold)";
  }

  // A loaded mesh is centered already (load_mesh, in double: its file's coordinates are
  // origin + positions); a procedural one is centered here.
  static PlacedMesh centered(Mesh m) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : m.positions) {
      lo = glm::min(lo, glm::dvec3(p));
      hi = glm::max(hi, glm::dvec3(p));
    }
    glm::dvec3 center = m.positions.empty() ? glm::dvec3(0.0) : (lo + hi) * 0.5;
    if (center != glm::dvec3(0.0))
      for (glm::vec3& p : m.positions) p = glm::vec3(glm::dvec3(p) - center);
    m.origin += center;
    glm::dvec3 origin = m.origin;
    return {std::make_shared<Mesh>(std::move(m)), origin};
  }

  // `faces`: decimated to about that many (common/mesh/decimate.hpp), or 0: as the file has it.
  PlacedMesh mesh_file(const std::string& relative, size_t faces = 0) {
    fs::path p = fs::path(relative).is_absolute() ? fs::path(relative) : fs::path(base_) / relative;
    std::string file = p.lexically_normal().string(), key = file + (faces ? "#" + std::to_string(faces) : "");
    auto it = meshes_.find(key);
    if (it != meshes_.end()) return it->second;
    return meshes_[key] = centered(faces ? decimate(*mesh_file(relative).mesh, faces) : load_mesh(file));
  }

  size_t decimate_to(const json& j, const std::string& path) const {
    if (!j.is_number_integer() || j.get<int64_t>() < int64_t(kMinDecimatedFaces) ||
        j.get<int64_t>() > int64_t(kMaxDecimatedFaces))
      fail(path, "expected a whole number of faces in " + std::to_string(kMinDecimatedFaces) + ".." +
                     std::to_string(kMaxDecimatedFaces));
    return size_t(j.get<int64_t>());
  }

  glm::dmat4 transform(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 16) fail(path, "expected 16 numbers (a column-major 4x4 matrix)");
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = exact_number(j[size_t(i)], path + "/" + std::to_string(i));
    for (int i : {3, 7, 11, 15})
      if (m[i / 4][3] != (i == 15 ? 1.0 : 0.0))
        fail(path + "/" + std::to_string(i),
             std::string("must be ") + (i == 15 ? "1" : "0") + " (the last row of an affine transform is 0, 0, 0, 1)");
    check_linear_part(glm::dmat3(m), path);
    return m;
  }

  // A relative test, so that a uniform scale of any size passes (kMaxTransformCondition).
  void check_linear_part(const glm::dmat3& a, const std::string& path) const {
    double det = glm::determinant(a);
    if (det == 0) fail(path, "is singular (its linear part flattens the mesh)");
    double condition = frobenius(a) * frobenius(glm::inverse(a));
    if (!(condition <= kMaxTransformCondition))
      fail(path, "is nearly singular: its linear part's condition number is " + format_number(condition) + ", over " +
                     format_number(kMaxTransformCondition));
    if (std::abs(det) < kMinTransformDeterminant || std::abs(det) > kMaxTransformDeterminant)
      fail(path, "scales volumes by " + format_number(det) + ", outside ±[" + format_number(kMinTransformDeterminant) +
                     ", " + format_number(kMaxTransformDeterminant) + "] (its normal matrix would not fit in float)");
  }

  static double frobenius(const glm::dmat3& a) {
    return std::sqrt(glm::dot(a[0], a[0]) + glm::dot(a[1], a[1]) + glm::dot(a[2], a[2]));
  }

  glm::vec3 color(const json& j, const std::string& path) const {
    glm::vec3 c = vec3(j, path);
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0 || c[k] > 1) fail(path + "/" + std::to_string(k), "must be in [0, 1]");
    return c;
  }

  Style style(const json& j, const std::string& path) const {
    const std::vector<std::string>& names = style_names();
    auto it = j.is_string() ? std::find(names.begin(), names.end(), j.get<std::string>()) : names.end();
    if (it == names.end()) fail(path, "expected " + join(names));
    return Style(it - names.begin());
  }

  // Near and far planes bracketing the scene's bounding sphere from the camera.
  static void fit_planes(const Scene& s, Camera& c) {
    glm::vec3 center;
    float radius;
    scene_bounds(s, center, radius);
    plumbago::fit_planes(c, center, radius);
  }

  std::string source_, base_;
  std::map<std::string, PlacedMesh> meshes_;
};

// The scene's effects. "sketchy" and "strokes" go with objects of those styles (Nienhaus & Döllner 2004; Kalnins et al.
// 2002): on by themselves when one is, refused when none is; so is "basecoat", which coats the
// stroke objects. Without "effects": contours for the pencil objects, the base coat for
// the stroke objects.
void set_effects(const json& j, const SceneReader& r, Scene& s) {
  s.effects.clear();
  if (j.contains("effects"))
    s.effects = r.effects(j["effects"], "/effects");
  else {
    if (has_style(s, Style::Pencil) || has_style(s, Style::Shaded)) s.effects.push_back("contours");
    if (has_style(s, Style::Strokes)) s.effects.push_back("basecoat");
  }
  for (const std::string& effect : s.effects)
    if (const StyleEffect* styled = style_effect(effect); styled && !has_style(s, styled->style))
      r.fail("/effects", "'" + effect + "' draws the objects whose style is " + style_names()[size_t(styled->style)] +
                             ", and no object has it");
  match_effects_to_styles(s);
}

// The center of the objects' world-space bounding box, in double: the scene's origin.
glm::dvec3 world_center(const std::vector<SceneReader::FileObject>& objects) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const SceneReader::FileObject& f : objects)
    for (const glm::vec3& p : f.object.mesh->positions) {
      glm::dvec3 w = f.world_position(p);
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  return lo.x <= hi.x ? (lo + hi) * 0.5 : glm::dvec3(0.0);
}

}  // namespace

void set_drawn_examples(Scene& s) {
  s.strokes.crease_examples.clear(), s.strokes.silhouette_examples.clear();
  for (const StrokeFile& file : s.stroke_files)
    for (size_t k = 0; k < file.strokes.size(); ++k) {
      const DrawnStroke& stroke = file.strokes[k];
      std::string where = file.source + ": /strokes/" + std::to_string(k);
      if (stroke.role == StrokeRole::Crease) s.strokes.crease_examples.push_back(drawn_offsets(stroke, where));
      if (stroke.role == StrokeRole::Silhouette) s.strokes.silhouette_examples.push_back(drawn_offsets(stroke, where));
    }
}

namespace {

Scene read_scene(const json& j, SceneReader& r, const std::string& source) {
  r.only_keys(j, "",
              {"mesh", "objects", "camera", "lights", "resolution", "seed", "effects", "params", "strokes", "animation",
               "stroke_files"});
  Scene s;
  s.source = source;
  if (j.contains("mesh") == j.contains("objects")) r.fail("", "give either \"mesh\" (one object) or \"objects\"");
  std::vector<SceneReader::FileObject> objects;
  if (j.contains("mesh")) {
    objects.push_back(r.placed(j["mesh"], "/mesh"));
    r.check_extent(objects.back(), "");
  } else {
    if (!j["objects"].is_array() || j["objects"].empty()) r.fail("/objects", "expected a non-empty array");
    for (size_t i = 0; i < j["objects"].size(); ++i)
      objects.push_back(r.object(j["objects"][i], "/objects/" + std::to_string(i)));
  }
  s.origin = world_center(objects);
  for (SceneReader::FileObject& f : objects) {  // T relative to the origin, in double, then float
    glm::dmat4 relative = f.transform;
    relative[3] = f.transform * glm::dvec4(f.mesh_center, 1.0) - glm::dvec4(s.origin, 0.0);  // T translate(c) - origin
    f.object.transform = glm::mat4(relative);
    s.objects.push_back(f.object);
  }
  if (j.contains("resolution")) r.resolution(j["resolution"], "/resolution", s);
  if (j.contains("seed")) {
    if (!j["seed"].is_number_unsigned() || j["seed"].get<uint64_t>() > 0xFFFFFFFFull)
      r.fail("/seed", "expected an integer in 0..4294967295");
    s.seed = uint32_t(j["seed"].get<uint64_t>());
  }
  set_effects(j, r, s);
  if (j.contains("params")) r.params(j["params"], "/params", s.params);
  if (j.contains("strokes")) s.strokes = r.stroke_styles(j["strokes"], "/strokes");
  if (j.contains("stroke_files")) s.stroke_files = r.stroke_files(j["stroke_files"], "/stroke_files", s.origin);
  set_drawn_examples(s);
  s.camera = j.contains("camera") ? r.camera(j["camera"], "/camera", s) : SceneReader::fitted_camera(s, 35.0f);
  r.check_camera(s, j.contains("camera") ? j["camera"] : json::object(), "/camera");
  s.lights_follow_camera = !j.contains("lights");
  s.lights = s.lights_follow_camera ? default_lights(s.camera) : r.lights(j["lights"], "/lights");
  if (j.contains("animation")) s.animation = r.animation(j["animation"], "/animation", s);
  return s;
}

}  // namespace

std::vector<Light> default_lights(const Camera& c) {
  glm::vec3 back = -c.forward();
  glm::vec3 right = glm::normalize(glm::cross(c.forward(), c.up));
  glm::vec3 up = glm::cross(right, c.forward());
  return {{glm::normalize(back + 0.6f * up - 0.5f * right), 1.0f}};
}

WindowBounds window_bounds(const Scene& scene, int width, int height) {
  glm::mat4 to_clip = scene.camera.projection(float(width) / float(height)) * scene.camera.view();
  WindowBounds b;
  for (const SceneObject& o : scene.objects) {
    glm::mat4 object_to_clip = to_clip * o.transform;
    for (const glm::vec3& v : o.mesh->positions) {  // a triangle's projection lies within its corners'
      glm::vec4 clip = object_to_clip * glm::vec4(v, 1.0f);
      if (!(clip.w > 0.0f)) return {.behind_eye = true};  // behind the eye: the projection does not bound it
      glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
      b.lo = glm::min(b.lo, pixel);
      b.hi = glm::max(b.hi, pixel);
    }
  }
  return b;
}

PixelRect covered_rect(const WindowBounds& bounds, int width, int height, float margin) {
  if (bounds.behind_eye) return {0, 0, width, height};
  glm::vec2 lo = bounds.lo, hi = bounds.hi;
  if (!(lo.x <= hi.x && lo.y <= hi.y)) return {};  // no object
  glm::ivec2 a = glm::ivec2(glm::floor(glm::clamp(lo - margin, glm::vec2(0), glm::vec2(width, height))));
  glm::ivec2 b = glm::ivec2(glm::ceil(glm::clamp(hi + margin, glm::vec2(0), glm::vec2(width, height))));
  return {a.x, a.y, b.x, b.y};
}

PixelRect covered_rect(const Scene& scene, int width, int height, float margin) {
  return covered_rect(window_bounds(scene, width, height), width, height, margin);
}

PixelRect filter_rect(const Scene& scene, int radius) {
  return covered_rect(scene, scene.width, scene.height, float(radius + 1));
}

PixelRect filter_rect(const WindowBounds& bounds, const Scene& scene, int radius) {
  return covered_rect(bounds, scene.width, scene.height, float(radius + 1));
}

void scene_bounds(const Scene& scene, glm::vec3& center, float& radius) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& o : scene.objects)
    for (const auto& p : o.mesh->positions) {
      glm::vec3 w(o.transform * glm::vec4(p, 1.0f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  center = (lo + hi) * 0.5f;
  radius = std::max(glm::length(hi - lo) * 0.5f, 1e-6f);
}

Scene parse_scene(const std::string& text, const std::string& source, const std::string& base_dir) {
  json j = parse_json_text_as<SceneError>(text, source);
  SceneReader reader(source, base_dir);
  return read_scene(j, reader, source);
}

std::string scene_text(const std::string& source) {
  if (source.starts_with("builtin:")) {
    auto it = kBuiltinScenes.find(source.substr(8));
    if (it == kBuiltinScenes.end())
      throw SceneError(source + ": no such built-in scene (" + join(builtin_scene_names()) + ")");
    return it->second;
  }
  return read_input_file_as<SceneError>(source, "scene file");
}

std::string scene_folder(const std::string& source) {
  fs::path dir = source.starts_with("builtin:") ? fs::path() : fs::path(source).parent_path();
  return dir.empty() ? "." : dir.string();
}

Scene load_scene(const std::string& path) { return parse_scene(scene_text(path), path, scene_folder(path)); }

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : kBuiltinScenes) names.push_back(name);
  return names;
}

Scene builtin_scene(const std::string& name) { return load_scene("builtin:" + name); }

const std::vector<std::string>& style_names() {
  static const std::vector<std::string> names = {"pencil", "sketchy", "shaded", "strokes"};
  return names;
}

const StyleEffect* style_effect(const std::string& effect) {
  static const std::map<std::string, StyleEffect> effects = {
      {"sketchy", {Style::Sketchy, true}}, {"strokes", {Style::Strokes, true}}, {"basecoat", {Style::Strokes, false}}};
  auto it = effects.find(effect);
  return it == effects.end() ? nullptr : &it->second;
}

bool has_style(const Scene& s, Style style) {
  return std::any_of(s.objects.begin(), s.objects.end(), [&](const SceneObject& o) { return o.style == style; });
}

void match_effects_to_styles(Scene& s) {
  std::erase_if(s.effects, [&](const std::string& e) {
    const StyleEffect* styled = style_effect(e);
    return styled && !has_style(s, styled->style);
  });
  for (const EffectDef& e : effect_table()) {
    const StyleEffect* styled = style_effect(e.name);
    bool listed = std::find(s.effects.begin(), s.effects.end(), e.name) != s.effects.end();
    if (styled && styled->automatic && has_style(s, styled->style) && !listed) s.effects.push_back(e.name);
  }
}

}  // namespace plumbago
