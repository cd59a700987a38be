#include "apps/viewer/script.hpp"

#include <algorithm>
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
  for (const auto& [name, on] : arg.items()) {
    bool known = std::any_of(table.begin(), table.end(), [&](const EffectDef& e) { return e.name == name; });
    require(known, "unknown effect '" + name + "' (plumbago effects lists them)");
    require(on.is_boolean(), name + ": true or false");
  }
}

void check_arg(const std::string& key, const json& arg) {
  if (key == "set") return check_set(arg);
  if (key == "effect") return check_effect(arg);
  if (key == "orbit")
    return require(arg.is_array() && arg.size() == 2 && arg[0].is_number() && arg[1].is_number(),
                   "takes [degrees about the up vector, degrees of pitch]");
  if (key == "reload") return require(arg.is_boolean() && arg.get<bool>(), "takes true");
  if (key == "stage" || key == "check" || key == "heatmap" || key == "save" || key == "screenshot")
    return require(arg.is_string() && (key == "stage" || key == "check" || !arg.get<std::string>().empty()),
                   "takes a string");
  throw std::invalid_argument("unknown action (set, effect, orbit, stage, check, heatmap, save, screenshot, reload)");
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
