// A number as every error message writes it.
#pragma once

#include <string>

namespace rigid_body_sim::core {

// printf's "%g": 0.5, -1, 1e+06, inf, nan. One spelling for "got ..." in every
// message, whichever layer checks the value.
std::string FormatNumber(double value);

}  // namespace rigid_body_sim::core
