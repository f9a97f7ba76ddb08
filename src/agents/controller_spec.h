// Which controller drives a node, at what rate, with which parameters (from the scenario).
#pragma once

#include <string>

#include "sanet/params.h"

namespace sanet::agents {

struct ControllerSpec {
  std::string name;     // registered name
  std::string library;  // shared library to load first ("" for built-in controllers)
  double rate = 10;     // Hz, control steps per second
  Params params;
};

}  // namespace sanet::agents
