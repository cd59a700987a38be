#include "common/core/param_text.hpp"

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
    for (const auto& c : s.choices) {
      if (!r.empty()) r += '|';
      r += c;
    }
    return r;
  }
  std::string r = "[";  // appended piece by piece: GCC 12's -Wrestrict misfires on chained + at -O3
  r += format_value(s, s.min);
  r += ", ";
  r += format_value(s, s.max);
  r += ']';
  return r;
}

}  // namespace plumbago
