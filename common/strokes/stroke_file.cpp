// Stroke files (Kalnins et al. 2002, §3, §4.5): see common/strokes/stroke_file.hpp.
#include "common/strokes/stroke_file.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/scene/json_position.hpp"
#include "common/scene/scene.hpp"
#include "common/util/input_file.hpp"

namespace plumbago {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr int kMaxResolution = 16384;  // as a scene's resolution

class StrokeFileReader {
 public:
  StrokeFileReader(std::string source, std::string base_dir) : source_(std::move(source)), base_(std::move(base_dir)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneError(source_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  StrokeFile file(const json& j, glm::dvec3 origin) const {
    only_keys(j, "", {"camera", "resolution", "style", "strokes"});
    StrokeFile out;
    out.source = source_;
    if (!j.contains("camera")) fail("/camera", "missing (the camera the strokes were drawn with)");
    if (!j.contains("resolution")) fail("/resolution", "missing (the window the strokes were drawn in)");
    resolution(j["resolution"], out);
    out.camera = camera(j["camera"], "/camera", origin);
    if (auto fault = camera_fault(out.camera, double(out.width) / out.height, origin))
      fail("/camera/" + fault->key, fault->what);
    if (j.contains("style")) out.style = text(j["style"], "/style");
    if (!j.contains("strokes") || !j["strokes"].is_array()) fail("/strokes", "expected an array of strokes");
    size_t points = 0;
    for (size_t i = 0; i < j["strokes"].size(); ++i) {
      out.strokes.push_back(stroke(j["strokes"][i], "/strokes/" + std::to_string(i), out.style));
      if ((points += out.strokes.back().points.size()) > kMaxDrawnPoints)
        fail("/strokes/" + std::to_string(i) + "/points",
             "the strokes hold over " + std::to_string(kMaxDrawnPoints) + " points, the most a stroke file may");
    }
    return out;
  }

 private:
  void only_keys(const json& j, const std::string& path, const std::vector<std::string>& allowed) const {
    if (!j.is_object()) fail(path, "expected an object");
    for (const auto& item : j.items())
      if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
        std::ostringstream list;
        for (size_t k = 0; k < allowed.size(); ++k) list << (k ? ", " : "") << allowed[k];
        fail(path + "/" + item.key(), "unknown key (known here: " + list.str() + ")");
      }
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number() || !std::isfinite(j.get<double>())) fail(path, "expected a finite number");
    return j.get<double>();
  }

  std::string text(const json& j, const std::string& path) const {
    if (!j.is_string() || j.get<std::string>().empty()) fail(path, "expected a non-empty string");
    return j.get<std::string>();
  }

  glm::dvec3 point(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected an array of 3 numbers");
    return {number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2")};
  }

  void resolution(const json& j, StrokeFile& out) const {
    if (!j.is_array() || j.size() != 2 || !j[0].is_number_integer() || !j[1].is_number_integer())
      fail("/resolution", "expected [width, height] in pixels");
    for (int k = 0; k < 2; ++k)
      if (j[k].get<int64_t>() < 1 || j[k].get<int64_t>() > kMaxResolution)
        fail("/resolution/" + std::to_string(k), "must be in 1.." + std::to_string(kMaxResolution));
    out.width = int(j[0].get<int64_t>()), out.height = int(j[1].get<int64_t>());
  }

  // Every key given: the strokes were drawn with one exact camera, nothing is fitted.
  Camera camera(const json& j, const std::string& path, glm::dvec3 origin) const {
    only_keys(j, path, {"eye", "target", "up", "fov_deg", "near", "far"});
    for (const char* key : {"eye", "target", "up", "fov_deg", "near", "far"})
      if (!j.contains(key)) fail(path + "/" + key, "missing");
    Camera c;
    c.eye = glm::vec3(point(j["eye"], path + "/eye") - origin);
    c.target = glm::vec3(point(j["target"], path + "/target") - origin);
    c.up = glm::vec3(point(j["up"], path + "/up"));
    c.fov_deg = float(number(j["fov_deg"], path + "/fov_deg"));
    c.near = float(number(j["near"], path + "/near"));
    c.far = float(number(j["far"], path + "/far"));
    return c;
  }

  DrawnStroke stroke(const json& j, const std::string& path, const std::string& file_style) const {
    only_keys(j, path, {"role", "points", "style", "group", "free", "mobile"});
    DrawnStroke s;
    s.role = role(j.contains("role") ? j["role"] : json(), path + "/role");
    if (!j.contains("points") || !j["points"].is_array() || j["points"].size() < 2)
      fail(path + "/points", "expected an array of 2 points or more, each [x, y, pressure]");
    for (size_t k = 0; k < j["points"].size(); ++k)
      s.points.push_back(drawn_point(j["points"][k], path + "/points/" + std::to_string(k)));
    if (j.contains("group") != (s.role == StrokeRole::Hatching))
      fail(path + "/group", s.role == StrokeRole::Hatching ? "missing (a hatching stroke's group)"
                                                           : "only hatching strokes have a group");
    if (j.contains("group")) {
      if (!j["group"].is_number_integer() || j["group"].get<int64_t>() < 0 ||
          j["group"].get<int64_t>() > kMaxHatchingGroup)
        fail(path + "/group", "expected a whole number in 0.." + std::to_string(kMaxHatchingGroup));
      s.group = int(j["group"].get<int64_t>());
    }
    if (j.contains("free")) {
      if (s.role != StrokeRole::Hatching) fail(path + "/free", "only hatching strokes are free or structured");
      if (!j["free"].is_boolean()) fail(path + "/free", "expected true or false");
      s.free = j["free"].get<bool>();
    }
    if (j.contains("mobile")) {
      if (s.role != StrokeRole::Hatching) fail(path + "/mobile", "only hatching strokes are mobile");
      if (!j["mobile"].is_boolean()) fail(path + "/mobile", "expected true or false");
      s.mobile = j["mobile"].get<bool>();
    }
    bool on_surface = s.role == StrokeRole::Decal || s.role == StrokeRole::Hatching;
    if (!on_surface)
      if (std::string fault = offsets_example_fault(s); !fault.empty()) fail(path + "/points", fault);
    if (j.contains("style") && !on_surface) fail(path + "/style", "only decals and hatching name a style");
    s.style_name = j.contains("style") ? text(j["style"], path + "/style") : file_style;
    if (on_surface)
      s.style = style(s.style_name.empty() ? kDefaultDecalStyle : s.style_name,
                      j.contains("style") ? path + "/style" : "/style");
    return s;
  }

  StrokeRole role(const json& j, const std::string& path) const {
    const std::vector<std::string>& names = stroke_role_names();
    auto it = j.is_string() ? std::find(names.begin(), names.end(), j.get<std::string>()) : names.end();
    if (it == names.end()) fail(path, "expected one of decal, crease, silhouette, hatching");
    return StrokeRole(it - names.begin());
  }

  DrawnPoint drawn_point(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, "expected [x, y, pressure]");
    DrawnPoint p{{number(j[0], path + "/0"), number(j[1], path + "/1")}, number(j[2], path + "/2")};
    if (std::abs(p.window.x) > kMaxDrawnPixel || std::abs(p.window.y) > kMaxDrawnPixel)
      fail(path, "lies beyond ±" + format_number(kMaxDrawnPixel) + " px");
    if (p.pressure < 0 || p.pressure > 1) fail(path + "/2", "pressure must be in [0, 1]");
    return p;
  }

  StrokeStyle style(const std::string& name, const std::string& path) const {
    try {
      return load_stroke_style_from(name, base_);
    } catch (const StrokeStyleError& e) {
      fail(path, e.what());
    }
  }

  std::string source_, base_;
};

json camera_document(const Camera& c, glm::dvec3 origin) {
  auto absolute = [&](glm::vec3 p) {
    glm::dvec3 w = glm::dvec3(p) + origin;
    return json::array({w.x, w.y, w.z});
  };
  return {{"eye", absolute(c.eye)},
          {"target", absolute(c.target)},
          {"up", json::array({c.up.x, c.up.y, c.up.z})},
          {"fov_deg", c.fov_deg},
          {"near", c.near},
          {"far", c.far}};
}

}  // namespace

const std::vector<std::string>& stroke_role_names() {
  static const std::vector<std::string> names = {"decal", "crease", "silhouette", "hatching"};
  return names;
}

StrokeFile parse_stroke_file(const std::string& text, const std::string& source, const std::string& base_dir,
                             glm::dvec3 origin) {
  return StrokeFileReader(source, base_dir).file(parse_json_text_as<SceneError>(text, source), origin);
}

StrokeFile load_stroke_file(const std::string& path, glm::dvec3 origin) {
  fs::path dir = fs::path(path).parent_path();
  return parse_stroke_file(read_input_file_as<SceneError>(path, "stroke file"), path, dir.empty() ? "." : dir.string(),
                           origin);
}

std::string offsets_example_fault(const DrawnStroke& stroke) {
  glm::dvec2 a = stroke.points.front().window, chord = stroke.points.back().window - a;
  double length = glm::length(chord);
  if (!(length >= 1))
    return "a crease or silhouette stroke is an offsets example: its ends must be 1 px apart or more (they are " +
           format_number(length) + " px apart)";
  glm::dvec2 left = glm::dvec2(-chord.y, chord.x) / length;
  for (const DrawnPoint& p : stroke.points)
    if (std::abs(glm::dot(p.window - a, left)) > 1000)
      return "an offsets example strays more than 1000 px from its chord";
  return "";
}

OffsetExample drawn_offsets(const DrawnStroke& stroke, const std::string& source) {
  if (std::string fault = offsets_example_fault(stroke); !fault.empty()) throw SceneError(source + ": " + fault);
  glm::dvec2 a = stroke.points.front().window, chord = stroke.points.back().window - a;
  double length = glm::length(chord);
  glm::dvec2 along = chord / length, left(-along.y, along.x);
  OffsetExample out{length, {}};
  double t = 0;
  for (const DrawnPoint& p : stroke.points) {
    t = std::clamp(std::max(t, glm::dot(p.window - a, along) / length), 0.0, 1.0);
    out.offsets.push_back({t, glm::dot(p.window - a, left), p.pressure, false});
  }
  return out;
}

std::string stroke_file_json(const StrokeFile& file, glm::dvec3 origin) {
  json strokes = json::array();
  for (const DrawnStroke& s : file.strokes) {
    json points = json::array();
    for (const DrawnPoint& p : s.points) points.push_back({p.window.x, p.window.y, p.pressure});
    json one = {{"role", stroke_role_names()[size_t(s.role)]}, {"points", points}};
    bool on_surface = s.role == StrokeRole::Decal || s.role == StrokeRole::Hatching;
    if (on_surface && !s.style_name.empty() && s.style_name != file.style) one["style"] = s.style_name;
    if (s.role == StrokeRole::Hatching) one["group"] = s.group;
    if (s.free) one["free"] = true;
    if (s.mobile) one["mobile"] = true;
    strokes.push_back(one);
  }
  // One line a key, one line a stroke: a file a person can read and edit.
  std::ostringstream out;
  out << "{\n \"camera\": " << camera_document(file.camera, origin).dump()
      << ",\n \"resolution\": " << json::array({file.width, file.height}).dump() << ",\n";
  if (!file.style.empty()) out << " \"style\": " << json(file.style).dump() << ",\n";
  out << " \"strokes\": [";
  for (size_t i = 0; i < strokes.size(); ++i) out << (i ? ",\n  " : "\n  ") << strokes[i].dump();
  out << "\n ]\n}\n";
  return out.str();
}

}  // namespace plumbago
