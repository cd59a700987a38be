// How a parameter is written for people: `plumbago params` and `plumbago stages`.
#pragma once

#include <string>

#include "common/core/params.hpp"

namespace plumbago {

const char* param_type_name(ParamType t);  // "real", "int", "bool", "choice"
// "[min, max]", "true|false", or the choices joined by '|'.
std::string param_range(const ParamSpec& s);

}  // namespace plumbago
