// How a parameter is written for people: `plumbago params`, `plumbago stages` and the Python
// module's params() (python/).
#pragma once

#include <string>

#include "common/core/params.hpp"

namespace plumbago {

const char* param_type_name(ParamType t);  // "real", "int", "bool", "choice"
// "[min, max]", "true|false", or the choices joined by '|'.
std::string param_range(const ParamSpec& s);

}  // namespace plumbago
