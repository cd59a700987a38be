#include "common/core/params.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/core/stage_registry.hpp"

namespace plumbago {

void SpecCollector::add(const char* name, ParamType t, double def, double lo, double hi,
                        std::vector<std::string> choices, const char* doc) {
  out_.push_back({stage_ + "." + name, t, def, lo, hi, std::move(choices), doc});
}

namespace {

// Each struct's specs, refusing a prefix that two structs share: in a fused shader their
// GLSL declarations (`uniform contour_params contour;`) would clash.
template <class... Structs>
void collect_specs(TypeList<Structs...>, std::vector<ParamSpec>& specs, std::set<std::string>& prefixes) {
  (
      [&] {
        if (!prefixes.insert(Structs::stage).second)
          throw std::logic_error(std::string("two parameter structs have the prefix '") + Structs::stage + "'");
        Structs s{};
        SpecCollector c{Structs::stage, specs};
        s.visit(c);
      }(),
      ...);
}

template <class... Stages>
std::vector<ParamSpec> collect_specs(TypeList<Stages...>) {
  std::vector<ParamSpec> specs;
  std::set<std::string> prefixes;
  (collect_specs(typename Stages::Params{}, specs, prefixes), ...);
  return specs;
}

std::string valid_names() {
  std::ostringstream os;
  for (const auto& s : param_specs()) os << "\n  " << s.key;
  return os.str();
}

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string range_text(const ParamSpec& s) {
  std::ostringstream os;
  switch (s.type) {
    case ParamType::Boolean:
      return "true or false";
    case ParamType::Choice:
      for (size_t i = 0; i < s.choices.size(); ++i) os << (i ? "|" : "") << s.choices[i];
      return os.str();
    default:
      os << "[" << s.min << ", " << s.max << "]";
      return os.str();
  }
}

double parse_number(const ParamSpec& spec, const std::string& text) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(v))
    throw ParamError("parameter '" + spec.key + "': '" + text + "' is not a number (valid: " + range_text(spec) + ")");
  return v;
}

double parse_value(const ParamSpec& spec, const std::string& text) {
  if (spec.type == ParamType::Boolean) {
    if (text == "true" || text == "1" || text == "on") return 1;
    if (text == "false" || text == "0" || text == "off") return 0;
    throw ParamError("parameter '" + spec.key + "': '" + text + "' is not true or false");
  }
  if (spec.type == ParamType::Choice) {
    for (size_t i = 0; i < spec.choices.size(); ++i)
      if (spec.choices[i] == text) return double(i);
    throw ParamError("parameter '" + spec.key + "': '" + text + "' is not one of " + range_text(spec));
  }
  return parse_number(spec, text);
}

}  // namespace

const std::vector<ParamSpec>& param_specs() {
  static const std::vector<ParamSpec> specs = collect_specs(AllStages{});
  return specs;
}

const ParamSpec& param_spec(const std::string& key) {
  for (const auto& s : param_specs())
    if (s.key == key) return s;
  throw ParamError("unknown parameter '" + key + "'; valid names:" + valid_names());
}

std::string format_value(const ParamSpec& spec, double value) {
  if (spec.type == ParamType::Boolean) return value != 0 ? "true" : "false";
  if (spec.type == ParamType::Choice) return spec.choices.at(size_t(value));
  return number_text(value);
}

void ParamSet::set(const std::string& key, double v) {
  const ParamSpec& spec = param_spec(key);
  bool integral = spec.type != ParamType::Real;
  if (!std::isfinite(v) || v < spec.min || v > spec.max || (integral && v != std::floor(v)))
    throw ParamError("parameter '" + key + "': " + number_text(v) + " is out of range (valid: " + range_text(spec) +
                     ")");
  overrides_[key] = v;
}

void ParamSet::set(const std::string& key, const std::string& text) { set(key, parse_value(param_spec(key), text)); }

void ParamSet::set_assignment(const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw ParamError("'" + assignment + "' is not of the form stage.name=value");
  set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

double ParamSet::value(const std::string& key) const {
  auto it = overrides_.find(key);
  return it != overrides_.end() ? it->second : param_spec(key).default_value;
}

}  // namespace plumbago
