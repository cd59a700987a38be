#include "apps/param_text.hpp"

namespace plumbago {

const char* param_type_name(ParamType t) {
  switch (t) {
    case ParamType::Real:
      return "real";
    case ParamType::Integer:
      return "int";
    case ParamType::Boolean:
      return "bool";
    default:
      return "choice";
  }
}

std::string param_range(const ParamSpec& s) {
  if (s.type == ParamType::Boolean) return "true|false";
  if (s.type == ParamType::Choice) {
    std::string r;
    for (const auto& c : s.choices) r += (r.empty() ? "" : "|") + c;
    return r;
  }
  return "[" + format_value(s, s.min) + ", " + format_value(s, s.max) + "]";
}

}  // namespace plumbago
