#include "apps/viewer/script.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/core/params.hpp"
#include "common/core/passes.hpp"

namespace plumbago {
namespace {

using nlohmann::json;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

void check_set(const json& arg) {
  require(arg.is_object() && !arg.empty(), "takes an object of parameter keys and values");
  for (const auto& [key, value] : arg.items()) param_value(key, value);
}

void check_effect(const json& arg) {
  require(arg.is_object() && !arg.empty(), "takes an object of effect names and true/false");
  const auto& table = effect_table();
  for (const auto& item : arg.items()) {
    const std::string& name = item.key();
    const json& on = item.value();
    bool known = std::any_of(table.begin(), table.end(), [&](const EffectDef& e) { return e.name == name; });
    require(known, "unknown effect '" + name + "' (plumbago effects lists them)");
    require(on.is_boolean(), name + ": true or false");
  }
}

bool finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

std::vector<DrawnPoint> drawn_points(const json& arg) {
  require(arg.contains("points") && arg["points"].is_array() && arg["points"].size() >= 2,
          "points: a list of 2 or more [x, y] (frame pixels, origin bottom-left)");
  const json& points = arg["points"];
  const json none = json::array();
  const json& pressure = arg.contains("pressure") ? arg["pressure"] : none;
  require(pressure.is_array() && (pressure.empty() || pressure.size() == points.size()),
          "pressure: a list of numbers in [0, 1], one a point");
  std::vector<DrawnPoint> out;
  for (size_t i = 0; i < points.size(); ++i) {
    const json& p = points[i];
    require(p.is_array() && p.size() == 2 && finite_number(p[0]) && finite_number(p[1]),
            "points[" + std::to_string(i) + "]: [x, y], two finite numbers");
    double w = pressure.empty() ? 1.0 : (finite_number(pressure[i]) ? pressure[i].get<double>() : -1.0);
    require(w >= 0 && w <= 1, "pressure[" + std::to_string(i) + "]: a number in [0, 1]");
    out.push_back({{p[0].get<double>(), p[1].get<double>()}, w});
  }
  return out;
}

void check_arg(const std::string& key, const json& arg) {
  if (key == "set") return check_set(arg);
  if (key == "effect") return check_effect(arg);
  if (key == "orbit")
    return require(arg.is_array() && arg.size() == 2 && arg[0].is_number() && arg[1].is_number(),
                   "takes [degrees about the up vector, degrees of pitch]");
  if (key == "reload") return require(arg.is_boolean() && arg.get<bool>(), "takes true");
  if (key == "draw") return (void)draw_request(arg);
  if (key == "undo" || key == "redo") return require(arg == "", "takes \"\"");
  if (key == "erase")
    return require(arg.is_array() && arg.size() == 2 && finite_number(arg[0]) && finite_number(arg[1]),
                   "takes [x, y]: frame pixels, origin bottom-left");
  if (key == "stage" || key == "check" || key == "heatmap" || key == "save" || key == "screenshot" ||
      key == "save_strokes")
    return require(arg.is_string() && (key == "stage" || key == "check" || !arg.get<std::string>().empty()),
                   "takes a string");
  throw std::invalid_argument(
      "unknown action (set, effect, orbit, stage, check, heatmap, save, screenshot, reload, draw, undo, redo, "
      "erase, save_strokes)");
}

ScriptAction parse_action(size_t index, const json& j) {
  require(j.is_object() && j.size() == 1, "an action is an object with one key");
  ScriptAction a{index, j.begin().key(), j.begin().value()};
  check_arg(a.key, a.arg);
  return a;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  require(bool(in), "cannot be read");
  try {
    return json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::invalid_argument(std::string("not JSON: ") + e.what());
  }
}

}  // namespace

double param_value(const std::string& key, const json& value) {
  require(value.is_number() || value.is_string() || value.is_boolean(), key + ": a number, string or boolean");
  ParamSet scratch;  // the value as --set takes it: name, type and range checked
  if (value.is_string())
    scratch.set(key, value.get<std::string>());
  else
    scratch.set(key, value.get<double>());
  return scratch.value(key);
}

DrawRequest draw_request(const json& arg) {
  require(arg.is_object(), "takes an object: kind, points, and optionally style, pressure, group, free");
  for (const auto& [key, value] : arg.items())
    require(key == "kind" || key == "points" || key == "style" || key == "pressure" || key == "group" ||
                key == "free" || key == "mobile",
            "unknown key '" + key + "' (kind, points, style, pressure, group, free, mobile)");
  const std::vector<std::string>& roles = stroke_role_names();
  const std::string kind = arg.contains("kind") && arg["kind"].is_string() ? arg["kind"].get<std::string>() : "";
  auto role = std::find(roles.begin(), roles.end(), kind);
  require(role != roles.end(), "kind: decal, crease, silhouette or hatching");
  DrawRequest r;
  r.role = StrokeRole(role - roles.begin());
  if (arg.contains("style")) {
    require(arg["style"].is_string() && !arg["style"].get<std::string>().empty(), "style: a preset or a style file");
    r.style = arg["style"].get<std::string>();
  }
  if (arg.contains("group"))
    require(arg["group"].is_number_integer() && arg["group"].get<int64_t>() >= 0 &&
                arg["group"].get<int64_t>() <= kMaxHatchingGroup,
            "group: a hatching group's number, 0 to " + std::to_string(kMaxHatchingGroup));
  r.group = arg.value("group", 0);
  require(!arg.contains("free") || arg["free"].is_boolean(), "free: true or false");
  r.free = arg.value("free", false);
  require(!arg.contains("mobile") || arg["mobile"].is_boolean(), "mobile: true or false");
  r.mobile = arg.value("mobile", false);
  r.points = drawn_points(arg);
  return r;
}

Script::Script(const std::string& path) : path_(path) {
  json j;
  try {
    j = read_json(path);
    require(j.is_array(), "a script is a JSON list of actions");
  } catch (const std::exception& e) {
    throw std::invalid_argument("--script " + path + ": " + e.what());
  }
  for (size_t i = 0; i < j.size(); ++i) {
    try {
      actions_.push_back(parse_action(i, j[i]));
    } catch (const std::exception& e) {
      throw std::invalid_argument(at(i, j[i].is_object() && !j[i].empty() ? j[i].begin().key() : "") + e.what());
    }
  }
}

std::string Script::at(size_t index, const std::string& key) const {
  std::ostringstream s;
  s << "--script " << path_ << ": action " << index;
  if (!key.empty()) s << " (" << key << ")";
  s << ": ";
  return s.str();
}

}  // namespace plumbago
